#pragma once
// The OpenGL functions the viewer may call, loaded at run time from whichever
// context is current (a GLFW window or an OSMesa buffer).
//
// Nothing links libGL directly: under OSMesa the glvnd dispatcher would send the
// calls nowhere. ImGui's stripped gl3w loader supplies most functions; the few
// it leaves out are loaded here beside it. Never include <GL/gl.h> or
// <GL/osmesa.h> in a file that includes this one.

#include <imgui_impl_opengl3_loader.h>

#include "app/gl/gl_proc.hpp"

#include <string>

extern "C" {
typedef void(APIENTRYP PFNJTGLTEXSUBIMAGE2DPROC)(GLenum target, GLint level, GLint xoffset,
                                                 GLint yoffset, GLsizei width, GLsizei height,
                                                 GLenum format, GLenum type, const void* pixels);
typedef void(APIENTRYP PFNJTGLGETTEXIMAGEPROC)(GLenum target, GLint level, GLenum format,
                                               GLenum type, void* pixels);
typedef void(APIENTRYP PFNJTGLFINISHPROC)(void);
extern PFNJTGLTEXSUBIMAGE2DPROC jt_glTexSubImage2D;
extern PFNJTGLGETTEXIMAGEPROC jt_glGetTexImage;
extern PFNJTGLFINISHPROC jt_glFinish;
}
#define glTexSubImage2D jt_glTexSubImage2D
#define glGetTexImage jt_glGetTexImage
#define glFinish jt_glFinish

// Constants the stripped loader leaves out (values from the OpenGL registry).
#ifndef GL_UNPACK_SKIP_ROWS
#define GL_UNPACK_SKIP_ROWS 0x0CF3
#endif
#ifndef GL_UNPACK_SKIP_PIXELS
#define GL_UNPACK_SKIP_PIXELS 0x0CF4
#endif
#ifndef GL_UNPACK_ALIGNMENT
#define GL_UNPACK_ALIGNMENT 0x0CF5
#endif
#ifndef GL_RGB
#define GL_RGB 0x1907
#endif
#ifndef GL_RGB8
#define GL_RGB8 0x8051
#endif
#ifndef GL_RGBA
#define GL_RGBA 0x1908
#endif
#ifndef GL_RGBA8
#define GL_RGBA8 0x8058
#endif
#ifndef GL_NEAREST
#define GL_NEAREST 0x2600
#endif
#ifndef GL_TEXTURE_WRAP_S
#define GL_TEXTURE_WRAP_S 0x2802
#define GL_TEXTURE_WRAP_T 0x2803
#endif
#ifndef GL_CLAMP_TO_EDGE
#define GL_CLAMP_TO_EDGE 0x812F
#endif

namespace jt::view {

// Loads every function above from `loader` for the context current now.
// Returns false and explains in `error` when a needed function is missing.
bool load_gl_functions(GlProcLoader loader, std::string& error);

}  // namespace jt::view
