// Desktop-only GL names that the shared code mentions in branches a WebGL 2 context never takes
// (each is behind a desktop-version, extension or capability test that answers no in the
// browser). They exist so that the same sources compile; reaching one is a bug, said loudly.
#pragma once
#include <stdint.h>
#include <stdio.h>

// Khronos names of desktop GL 4.x / KHR_debug tokens (values from the GL registry).
#include "desktop_gl_enums.h"

#ifdef __cplusplus
namespace oasis_web {
inline void unreachable(const char* name) { fprintf(stderr, "oasis web: desktop-only %s called\n", name); }
}  // namespace oasis_web
#define OASIS_WEB_UNREACHABLE(name) oasis_web::unreachable(name)


inline void glBeginConditionalRender(GLuint, GLenum) { OASIS_WEB_UNREACHABLE("glBeginConditionalRender"); }
inline void glEndConditionalRender() { OASIS_WEB_UNREACHABLE("glEndConditionalRender"); }
inline void glClipControl(GLenum, GLenum) { OASIS_WEB_UNREACHABLE("glClipControl"); }
inline void glDebugMessageInsert(GLenum, GLenum, GLuint, GLenum, GLsizei, const char*) {}
inline void glDispatchCompute(GLuint, GLuint, GLuint) { OASIS_WEB_UNREACHABLE("glDispatchCompute"); }
inline void glDrawBuffer(GLenum) { OASIS_WEB_UNREACHABLE("glDrawBuffer"); }
inline void glFrameTerminatorGREMEDY() {}
// WebGL 2's getBufferSubData, in emscripten's library_webgl2.js (ES 3.0 has no such call).
extern "C" void glGetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, void* data);
inline void glGetTextureLevelParameteriv(GLuint, GLint, GLenum, GLint* v) { OASIS_WEB_UNREACHABLE("glGetTextureLevelParameteriv"); if (v) *v = 0; }
inline void glGetObjectLabel(GLenum, GLuint, GLsizei, GLsizei* length, char*) { if (length) *length = 0; }
inline GLuint glGetProgramResourceIndex(GLuint, GLenum, const char*) { OASIS_WEB_UNREACHABLE("glGetProgramResourceIndex"); return 0xFFFFFFFFu; }
inline void glGetQueryObjectui64v(GLuint, GLenum, uint64_t* v) { OASIS_WEB_UNREACHABLE("glGetQueryObjectui64v"); if (v) *v = 0; }
inline void glMemoryBarrier(GLbitfield) { OASIS_WEB_UNREACHABLE("glMemoryBarrier"); }
inline void glObjectLabel(GLenum, GLuint, GLsizei, const char*) {}
inline void glPolygonMode(GLenum, GLenum) { OASIS_WEB_UNREACHABLE("glPolygonMode"); }
inline void glPushDebugGroup(GLenum, GLuint, GLsizei, const char*) {}
inline void glPopDebugGroup() {}
inline void glShaderStorageBlockBinding(GLuint, GLuint, GLuint) { OASIS_WEB_UNREACHABLE("glShaderStorageBlockBinding"); }
#endif
