#include "app/panels/panels.hpp"
#include "app/panels/property_fields.hpp"
#include "app/panels/widgets.hpp"

#include <imgui.h>

namespace jt::view {

bool material_editor(Material& m) {
    bool changed = edit_properties(m);
    changed = edit_file_name("image_map", m.image_map,
                             "A PNG, JPEG or BMP file, relative to the scene's folder, mapped "
                             "onto the object (map_size is one tile); empty: none. Enter "
                             "applies it.") ||
              changed;
    return changed;
}

}  // namespace jt::view
