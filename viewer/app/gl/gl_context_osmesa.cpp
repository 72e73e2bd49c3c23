#include "app/gl/gl_context_osmesa.hpp"

// Kept apart from gl.hpp: osmesa.h brings in <GL/gl.h>, which clashes with
// ImGui's loader header.
#include <GL/osmesa.h>

#include <cstdint>
#include <vector>

namespace jt::view {

struct OsMesaContext::Handle {
    OSMesaContext context = nullptr;
    std::vector<std::uint8_t> buffer;  // RGBA, rows bottom-up
};

OsMesaContext::OsMesaContext(int width, int height) : handle_(std::make_unique<Handle>()) {
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              0,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    handle_->context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!handle_->context) {
        error_ = "OSMesa could not create an OpenGL 3.3 core context";
        return;
    }
    resize(width, height);
}

OsMesaContext::~OsMesaContext() {
    if (handle_->context) OSMesaDestroyContext(handle_->context);
}

bool OsMesaContext::resize(int width, int height) {
    if (!handle_->context) return false;
    if (width < 1 || height < 1 || width > 16384 || height > 16384) {
        error_ = "the offscreen size must be between 1x1 and 16384x16384";
        return false;
    }
    handle_->buffer.assign(static_cast<std::size_t>(width) * height * 4, 0);
    if (!OSMesaMakeCurrent(handle_->context, handle_->buffer.data(), GL_UNSIGNED_BYTE, width,
                           height)) {
        error_ = "OSMesa could not make its context current";
        return false;
    }
    width_ = width;
    height_ = height;
    return true;
}

GlProcLoader OsMesaContext::proc_loader() {
    return [](const char* name) -> GlProc { return OSMesaGetProcAddress(name); };
}

}  // namespace jt::view
