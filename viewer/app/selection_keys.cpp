#include "app/selection_keys.hpp"

#include "app/keys.hpp"
#include "model/selection_commands.hpp"

#include <imgui.h>

namespace jt::view {

namespace {

bool pressed(int key) {
    return ImGui::IsKeyPressed(key, false);
}

}  // namespace

void selection_keys(AppState& state) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool d = pressed(keys::letter('D'));
    if (io.KeyCtrl) {
        if (d) duplicate_selection(state);
        return;
    }
    if (io.KeyAlt) return;
    if (pressed(keys::del) || pressed(keys::letter('X'))) delete_selection(state);
    if (io.KeyShift && d) duplicate_selection(state);
    if (pressed(keys::period) || pressed(keys::keypad_decimal)) frame_selection(state);
}

}  // namespace jt::view
