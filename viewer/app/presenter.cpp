#include "app/presenter.hpp"

#include "app/gl/gl.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdint>

namespace jt::view {

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
    } else {
        const PixelRect whole{0, 0, width_, height_};
        const PixelRect c = changed.value_or(whole);
        // Clip: a rectangle from a job of another size must never read out of bounds.
        const PixelRect r{std::max(c.x0, 0), std::max(c.y0, 0), std::min(c.x1, width_),
                          std::min(c.y1, height_)};
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
    // The image is opaque: drawn without blending, a software OpenGL need not
    // read back the pixels under it. The callback after it restores ImGui's state.
    draw_list->AddCallback([](const ImDrawList*, const ImDrawCmd*) { glDisable(GL_BLEND); },
                           nullptr);
    // Texture row 0 is the image's bottom row; ImGui's y runs down.
    draw_list->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture_)),
                        ImVec2(where.x0, where.y0), ImVec2(where.x1, where.y1), ImVec2(0, 1),
                        ImVec2(1, 0));
    draw_list->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
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
