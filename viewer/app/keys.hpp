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
inline constexpr int equal = 61;  // '+' on most layouts is Shift and this key
inline constexpr int keypad_1 = 321;
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

}  // namespace jt::view::keys

namespace jt::view {

// Fills io.KeyMap with the codes above, as the GLFW backend would.
void use_glfw_key_codes(ImGuiIO& io);

}  // namespace jt::view
