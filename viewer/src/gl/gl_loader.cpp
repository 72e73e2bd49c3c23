// The one translation unit that holds ImGui's gl3w loader implementation.
#define IMGL3W_IMPL
#include "gl/gl.hpp"

extern "C" {
PFNJTGLTEXSUBIMAGE2DPROC jt_glTexSubImage2D = nullptr;
PFNJTGLGETTEXIMAGEPROC jt_glGetTexImage = nullptr;
PFNJTGLFINISHPROC jt_glFinish = nullptr;
}

namespace jt::view {

bool load_gl_functions(GlProcLoader loader, std::string& error) {
    if (imgl3wInit2(loader) != GL3W_OK) {
        error = "the OpenGL context is not version 3.3 or later, or its functions cannot be loaded";
        return false;
    }
    jt_glTexSubImage2D = reinterpret_cast<PFNJTGLTEXSUBIMAGE2DPROC>(loader("glTexSubImage2D"));
    jt_glGetTexImage = reinterpret_cast<PFNJTGLGETTEXIMAGEPROC>(loader("glGetTexImage"));
    jt_glFinish = reinterpret_cast<PFNJTGLFINISHPROC>(loader("glFinish"));
    if (!jt_glTexSubImage2D || !jt_glGetTexImage || !jt_glFinish || !glReadPixels ||
        !glTexImage2D) {
        error = "the OpenGL context lacks glTexSubImage2D, glGetTexImage or glReadPixels";
        return false;
    }
    return true;
}

}  // namespace jt::view
