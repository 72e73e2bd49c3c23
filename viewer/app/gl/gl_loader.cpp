// The one translation unit that holds ImGui's gl3w loader implementation.
#define IMGL3W_IMPL
#include "app/gl/gl.hpp"

#include <cstring>

extern "C" {
PFNJTGLTEXSUBIMAGE2DPROC jt_glTexSubImage2D = nullptr;
PFNJTGLGETTEXIMAGEPROC jt_glGetTexImage = nullptr;
PFNJTGLFINISHPROC jt_glFinish = nullptr;
}

namespace jt::view {

namespace {

// imgl3wInit2 as shipped with ImGui 1.86 loads 54 names into its 53-slot
// `ptr` array; the 54th lands in the union's struct view, but it is still an
// out-of-bounds index (UBSan stops there). Fill the union through its full size.
bool load_imgui_procs(GlProcLoader loader) {
    constexpr std::size_t name_count = sizeof(proc_names) / sizeof(proc_names[0]);
    static_assert(name_count * sizeof(GL3WglProc) <= sizeof(imgl3wProcs));
    GL3WglProc slots[name_count];
    for (std::size_t i = 0; i < name_count; ++i) slots[i] = loader(proc_names[i]);
    std::memcpy(&imgl3wProcs, slots, sizeof(slots));
    return parse_version() == GL3W_OK;
}

}  // namespace

bool load_gl_functions(GlProcLoader loader, std::string& error) {
    if (!load_imgui_procs(loader)) {
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
