#include "panels/panels.hpp"
#include "panels/property_fields.hpp"

#include <imgui.h>

namespace jt::view {

bool material_editor(Material& m) {
    return edit_properties(m);
}

}  // namespace jt::view
