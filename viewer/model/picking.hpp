#pragma once
// Picking in the image: what a pixel shows (the core's pick_primitive on the
// frame the render draws), where the lights appear, and selection by click.
// Pixels are Image8's: x from the left, y from the bottom (docs/language.md §7.3).

#include "model/app_state.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace jt::view {

// The frame the image on screen is rendered from, or null while none is
// prepared or the scene's objects changed since (their indices would not match).
std::shared_ptr<const PreparedFrame> shown_frame(AppState& state);

// The primitive pixel (x, y) of the image shows, and its distance.
std::optional<PickedPrimitive> primitive_at(AppState& state, int x, int y);

// Where each light of the scene appears in the image (lights behind the
// camera have none).
struct LightMarker {
    int light = -1;
    ImagePoint at;  // image pixels from the bottom left corner
};
std::vector<LightMarker> light_markers(AppState& state);

// Selects `selection` and asks its panel to open and scroll to it.
void select(ViewState& view, Selection selection);
// Selects what a click at image point (x, y) shows: a light whose marker lies
// within `marker_radius` pixels first, else the primitive; the background
// clears the selection.
void select_at(AppState& state, double x, double y, double marker_radius);
// The selection while it still names a primitive or light of the scene, else none.
Selection current_selection(const ViewState& view, const Scene& scene);

// The figures of mesh `primitive` of the scene (its model from the shared
// cache), kept in state.view.mesh_figures until the scene or the selection changes.
const Expected<MeshInfo>& mesh_figures(AppState& state, int primitive);

// The ids of the primitives every pixel shows, once computed off the UI
// thread (asked for here), or null until then.
std::shared_ptr<const PrimitiveIdImage> shown_primitive_ids(AppState& state);

}  // namespace jt::view
