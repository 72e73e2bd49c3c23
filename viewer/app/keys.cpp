#include "app/keys.hpp"

#include <imgui.h>

namespace jt::view {

void use_glfw_key_codes(ImGuiIO& io) {
    io.KeyMap[ImGuiKey_Tab] = keys::tab;
    io.KeyMap[ImGuiKey_LeftArrow] = keys::left;
    io.KeyMap[ImGuiKey_RightArrow] = keys::right;
    io.KeyMap[ImGuiKey_UpArrow] = keys::up;
    io.KeyMap[ImGuiKey_DownArrow] = keys::down;
    io.KeyMap[ImGuiKey_Home] = keys::home;
    io.KeyMap[ImGuiKey_End] = keys::end;
    io.KeyMap[ImGuiKey_Delete] = keys::del;
    io.KeyMap[ImGuiKey_Backspace] = keys::backspace;
    io.KeyMap[ImGuiKey_Space] = keys::space;
    io.KeyMap[ImGuiKey_Enter] = keys::enter;
    io.KeyMap[ImGuiKey_Escape] = keys::escape;
    io.KeyMap[ImGuiKey_A] = keys::letter('A');
    io.KeyMap[ImGuiKey_C] = keys::letter('C');
    io.KeyMap[ImGuiKey_V] = keys::letter('V');
    io.KeyMap[ImGuiKey_X] = keys::letter('X');
    io.KeyMap[ImGuiKey_Y] = keys::letter('Y');
    io.KeyMap[ImGuiKey_Z] = keys::letter('Z');
}

}  // namespace jt::view
