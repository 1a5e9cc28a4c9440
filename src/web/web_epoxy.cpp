// libepoxy's version and extension queries for the web build (src/gl/web_shim/epoxy/gl.h): WebGL 2
// is OpenGL ES 3.0 and never desktop GL; extensions are the ones the browser enabled, GL_ prefixed.
#include <epoxy/gl.h>

#include <cstring>

// The dispatch pointers (src/gl/web_shim/epoxy/gl.h), pointing at the ES 3 functions themselves.
#undef glClearBufferfv
#undef glClearBufferfi
#undef glBeginQuery
#undef glEndQuery
PFNGLCLEARBUFFERFVPROC epoxy_glClearBufferfv = glClearBufferfv;
PFNGLCLEARBUFFERFIPROC epoxy_glClearBufferfi = glClearBufferfi;
PFNGLBEGINQUERYPROC epoxy_glBeginQuery = glBeginQuery;
PFNGLENDQUERYPROC epoxy_glEndQuery = glEndQuery;

extern "C" int epoxy_gl_version(void) { return 30; }

extern "C" bool epoxy_is_desktop_gl(void) { return false; }

extern "C" bool epoxy_has_gl_extension(const char* extension) {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const char* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
        if (name && std::strcmp(name, extension) == 0) return true;
    }
    return false;
}
