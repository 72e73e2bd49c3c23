#include "panels/panels.hpp"
#include "panels/widgets.hpp"

#include <imgui.h>

namespace jt::view {

void material_editor(Material& m) {
    edit_colour("pigment", m.pigment);
    edit_colour("ambient", m.ambient);
    edit_colour("diffuse", m.diffuse);
    edit_colour("specular", m.specular);
    edit_number("diffuse_k", m.diffuse_k, 0.01f, 0.01, 100.0);
    edit_number("specular_k", m.specular_k, 0.5f, 0.01, 10000.0);
    edit_number("reflection", m.reflection, 0.005f, 0.0, 1.0);
}

}  // namespace jt::view
