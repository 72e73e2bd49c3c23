#include "presenter.hpp"

#include "gl/gl.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace jt::view {

ScreenRect place_image(int image_w, int image_h, ScreenRect area, float framebuffer_scale,
                       FitMode mode) {
    if (image_w <= 0 || image_h <= 0 || area.width() <= 0 || area.height() <= 0) return {};
    const float aspect = static_cast<float>(image_w) / static_cast<float>(image_h);
    float w = 0, h = 0;
    if (mode == FitMode::actual_pixels) {
        const float scale = framebuffer_scale > 0 ? framebuffer_scale : 1.0f;
        w = static_cast<float>(image_w) / scale;
        h = static_cast<float>(image_h) / scale;
    } else if (area.width() / area.height() > aspect) {
        h = area.height();
        w = h * aspect;
    } else {
        w = area.width();
        h = w / aspect;
    }
    // Snap to whole framebuffer pixels so a 1:1 image is not resampled.
    const float s = framebuffer_scale > 0 ? framebuffer_scale : 1.0f;
    const float x0 = std::floor((area.x0 + (area.width() - w) * 0.5f) * s) / s;
    const float y0 = std::floor((area.y0 + (area.height() - h) * 0.5f) * s) / s;
    return {x0, y0, x0 + w, y0 + h};
}

Presenter::~Presenter() {
    if (texture_ != 0) glDeleteTextures(1, &texture_);
}

void Presenter::upload(const Image8& image, std::optional<PixelRect> changed) {
    if (image.width <= 0 || image.height <= 0) return;
    if (texture_ == 0) glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, image.width);
    if (image.width != width_ || image.height != height_) {
        width_ = image.width;
        height_ = image.height;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, width_, height_, 0, GL_RGB, GL_UNSIGNED_BYTE,
                     image.rgb.data());
        texels_uploaded_ += static_cast<long long>(width_) * height_;
    } else if (changed && !changed->empty()) {
        // Clip: a rectangle from a job of another size must never read out of bounds.
        const PixelRect r{std::max(changed->x0, 0), std::max(changed->y0, 0),
                          std::min(changed->x1, width_), std::min(changed->y1, height_)};
        if (!r.empty()) {
            glPixelStorei(GL_UNPACK_SKIP_PIXELS, r.x0);
            glPixelStorei(GL_UNPACK_SKIP_ROWS, r.y0);
            glTexSubImage2D(GL_TEXTURE_2D, 0, r.x0, r.y0, r.width(), r.height(), GL_RGB,
                            GL_UNSIGNED_BYTE, image.rgb.data());
            texels_uploaded_ += static_cast<long long>(r.width()) * r.height();
        }
    }
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

void Presenter::draw(ImDrawList* draw_list, ScreenRect where) const {
    if (!has_image() || where.width() <= 0) return;
    // Texture row 0 is the image's bottom row; ImGui's y runs down.
    draw_list->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture_)),
                        ImVec2(where.x0, where.y0), ImVec2(where.x1, where.y1), ImVec2(0, 1),
                        ImVec2(1, 0));
}

Image8 Presenter::read_texture() const {
    if (!has_image()) return {};
    Image8 image(width_, height_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_BYTE, image.rgb.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return image;
}

}  // namespace jt::view
