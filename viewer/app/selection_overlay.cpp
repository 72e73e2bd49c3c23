#include "app/selection_overlay.hpp"

#include "app/gl/gl.hpp"
#include "model/picking.hpp"

#include <imgui.h>

#include <cstdint>
#include <vector>

namespace jt::view {

namespace {

constexpr std::uint8_t kTint[4] = {255, 170, 40, 70};      // over the selected surface
constexpr std::uint8_t kOutline[4] = {255, 200, 60, 255};  // at its edge

ImTextureID texture_id(unsigned texture) {
    return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture));
}

}  // namespace

float light_marker_radius() {
    return ImGui::GetFontSize() * 0.45f;
}

SelectionOverlay::~SelectionOverlay() {
    if (texture_ != 0) glDeleteTextures(1, &texture_);
}

void SelectionOverlay::rebuild(const PrimitiveIdImage& ids, int primitive) {
    const int w = ids.width, h = ids.height;
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w) * h * 4, 0);
    outlined_ = 0;
    const auto is_it = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < w && y < h && ids.at(x, y) == primitive;
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!is_it(x, y)) continue;
            ++outlined_;
            const bool edge =
                !is_it(x - 1, y) || !is_it(x + 1, y) || !is_it(x, y - 1) || !is_it(x, y + 1);
            const std::uint8_t* c = edge ? kOutline : kTint;
            std::copy_n(c, 4, &rgba[(static_cast<std::size_t>(y) * w + x) * 4]);
        }
    if (texture_ == 0) glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
}

void SelectionOverlay::draw(AppState& state, ImDrawList* draw_list, const ScreenRect& where,
                            int image_w, int image_h) {
    if (where.width() <= 0 || image_w <= 0) return;
    const Selection selected = current_selection(state.view, state.doc.scene);
    if (selected.kind == Selection::Kind::primitive) {
        const std::shared_ptr<const PrimitiveIdImage> ids = shown_primitive_ids(state);
        if (ids && ids->width == image_w && ids->height == image_h) {
            if (ids != ids_ || selected.index != primitive_) {
                rebuild(*ids, selected.index);
                ids_ = ids;
                primitive_ = selected.index;
            }
            // Texture row 0 is the image's bottom row; ImGui's y runs down.
            draw_list->AddImage(texture_id(texture_), ImVec2(where.x0, where.y0),
                                ImVec2(where.x1, where.y1), ImVec2(0, 1), ImVec2(1, 0));
        }
    } else {
        outlined_ = 0;
    }
    const float r = light_marker_radius();
    for (const LightMarker& m : light_markers(state)) {
        const WindowPoint p = image_to_window(where, image_w, image_h, m.at);
        if (p.x < where.x0 || p.x > where.x1 || p.y < where.y0 || p.y > where.y1) continue;
        const bool chosen = selected.kind == Selection::Kind::light && selected.index == m.light;
        const ImU32 fill = chosen ? IM_COL32(255, 200, 60, 255) : IM_COL32(255, 245, 190, 220);
        draw_list->AddCircleFilled(ImVec2(p.x, p.y), r, IM_COL32(0, 0, 0, 160));
        draw_list->AddCircleFilled(ImVec2(p.x, p.y), r * 0.65f, fill);
        if (chosen) draw_list->AddCircle(ImVec2(p.x, p.y), r * 1.6f, fill, 0, 2.0f);
    }
}

}  // namespace jt::view
