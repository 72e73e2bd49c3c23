#include "panels/panels.hpp"
#include "panels/property_fields.hpp"

#include <imgui.h>

namespace jt::view {

void material_editor(Material& m) {
    edit_properties(m);
}

}  // namespace jt::view
