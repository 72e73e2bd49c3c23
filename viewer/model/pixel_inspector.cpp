#include "model/pixel_inspector.hpp"

#include "jtracer/schema.hpp"
#include "model/picking.hpp"

#include <cstdio>

namespace jt::view {

std::optional<PixelReport> inspect_pixel(AppState& state, int x, int y) {
    const Image8& image = state.render.display;
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return std::nullopt;
    PixelReport report;
    report.x = x;
    report.y = flipped_row(y, image.height);
    const std::uint8_t* p = image.pixel(x, y);
    report.rgb = {p[0], p[1], p[2]};
    report.earlier_render = !state.render.display_complete && state.render.passes_shown == 0;
    if (report.earlier_render) return report;
    // Objects deleted and added may leave as many as before: only the
    // revision tells that the image is of the scene as it stands.
    const bool current =
        state.render.started && state.render.started->scene_revision == state.doc.revision;
    if (const std::shared_ptr<const PreparedFrame> frame = current ? shown_frame(state) : nullptr)
        report.hit = pick_primitive(*frame, x, y);
    else
        report.earlier_scene = true;
    return report;
}

std::string describe(const PixelReport& r, const Scene& scene) {
    char text[160];
    std::snprintf(text, sizeof text, "x %d, y %d   RGB %d %d %d = %.3f %.3f %.3f\n", r.x, r.y,
                  r.rgb[0], r.rgb[1], r.rgb[2], r.rgb[0] / 255.0, r.rgb[1] / 255.0,
                  r.rgb[2] / 255.0);
    std::string line = text;
    if (r.earlier_render) return line + "(rendering: the pixel is of the render before)";
    if (r.earlier_scene) return line + "(the image is of an earlier scene, not rendered since)";
    if (!r.hit || static_cast<std::size_t>(r.hit->primitive) >= scene.primitives.size())
        return line + "background";
    const Primitive& p = scene.primitives[static_cast<std::size_t>(r.hit->primitive)];
    std::snprintf(text, sizeof text, "%s %d at distance %.4g",
                  std::string(keyword_of(p.shape)).c_str(), r.hit->primitive + 1, r.hit->distance);
    return line + text;
}

}  // namespace jt::view
