#pragma once
// Key codes for the viewer's shortcuts. They are GLFW's codes, which the ImGui
// GLFW backend stores in io.KeysDown[]; the headless path uses the same codes,
// so tests can press keys without GLFW.

struct ImGuiIO;

namespace jt::view::keys {

inline constexpr int space = 32;
inline constexpr int letter(char c) {
    return c;
}  // GLFW: 'A'..'Z' are their ASCII codes
inline constexpr int digit(char c) {
    return c;
}  // GLFW: '0'..'9' too
inline constexpr int minus = 45;
inline constexpr int period = 46;
inline constexpr int equal = 61;  // '+' on most layouts is Shift and this key
inline constexpr int keypad_1 = 321;
inline constexpr int keypad_decimal = 330;
inline constexpr int keypad_subtract = 333;
inline constexpr int keypad_add = 334;
inline constexpr int escape = 256;
inline constexpr int enter = 257;
inline constexpr int tab = 258;
inline constexpr int backspace = 259;
inline constexpr int del = 261;
inline constexpr int right = 262;
inline constexpr int left = 263;
inline constexpr int down = 264;
inline constexpr int up = 265;
inline constexpr int home = 268;
inline constexpr int end = 269;
inline constexpr int left_shift = 340;
inline constexpr int left_ctrl = 341;
inline constexpr int left_alt = 342;
inline constexpr int right_shift = 344;
inline constexpr int right_ctrl = 345;
inline constexpr int right_alt = 346;

}  // namespace jt::view::keys

namespace jt::view {

// GLFW's key actions (GLFW_PRESS, GLFW_RELEASE).
inline constexpr int kKeyPress = 1;
inline constexpr int kKeyRelease = 0;

// Fills io.KeyMap with the codes above, as the GLFW backend would.
void use_glfw_key_codes(ImGuiIO& io);

}  // namespace jt::view
