#pragma once
// An offscreen OpenGL 3.3 core context in main memory (Mesa's llvmpipe through
// OSMesa): no display, no GPU. The headless --screenshot path and the tests
// run the viewer's frame code in it.

#include "app/gl/gl_proc.hpp"

#include <memory>
#include <string>

namespace jt::view {

class OsMesaContext {
  public:
    // Creates the context and makes it current with a width x height buffer.
    // On failure, ok() is false and error() says why.
    OsMesaContext(int width, int height);
    ~OsMesaContext();
    OsMesaContext(const OsMesaContext&) = delete;
    OsMesaContext& operator=(const OsMesaContext&) = delete;

    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }
    int width() const { return width_; }
    int height() const { return height_; }

    // Reallocates the colour buffer and makes the context current with it.
    bool resize(int width, int height);
    static GlProcLoader proc_loader();

  private:
    struct Handle;
    std::unique_ptr<Handle> handle_;
    int width_ = 0;
    int height_ = 0;
    std::string error_;
};

}  // namespace jt::view
