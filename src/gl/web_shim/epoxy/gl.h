// The web build's stand-in for libepoxy's <epoxy/gl.h>: WebGL 2 is OpenGL ES 3.0, so the ES 3
// headers declare the calls; the few desktop-only names the shared code mentions (in branches
// a WebGL 2 context never takes) come from desktop_gl.h, and epoxy's queries from web_epoxy.cpp.
#pragma once
#include <GLES3/gl3.h>
#include <GLES2/gl2ext.h>

#include "desktop_gl.h"

// libepoxy's calling convention of its dispatch functions (nothing outside Windows).
#ifndef EPOXY_CALLSPEC
#define EPOXY_CALLSPEC
#endif

#ifdef __cplusplus
extern "C" {
#endif
// libepoxy's version and extension queries, answered from the WebGL 2 context (web_epoxy.cpp).
int epoxy_gl_version(void);
bool epoxy_is_desktop_gl(void);
bool epoxy_has_gl_extension(const char* extension);
// libepoxy's dispatch pointers for the calls frame/frame_traffic.cpp swaps while it counts a frame's
// clears and queries; as in libepoxy, the gl* names call through them (web_epoxy.cpp sets them to
// the ES 3 functions).
extern PFNGLCLEARBUFFERFVPROC epoxy_glClearBufferfv;
extern PFNGLCLEARBUFFERFIPROC epoxy_glClearBufferfi;
extern PFNGLBEGINQUERYPROC epoxy_glBeginQuery;
extern PFNGLENDQUERYPROC epoxy_glEndQuery;
#define glClearBufferfv epoxy_glClearBufferfv
#define glClearBufferfi epoxy_glClearBufferfi
#define glBeginQuery epoxy_glBeginQuery
#define glEndQuery epoxy_glEndQuery
#ifdef __cplusplus
}
#endif
