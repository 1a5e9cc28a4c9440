// The web build's half of context/gl_context.h: the page owns the WebGL 2 context (web_app.cpp),
// so only the queries are here. GL_RENDERER in a browser is masked ("WebKit WebGL"); the driver's
// own strings come from WEBGL_debug_renderer_info where the browser offers it.
#include "context/gl_context.h"

#include <emscripten.h>
#include <emscripten/html5.h>
#include <epoxy/gl.h>

#include <stdexcept>

#include <cstdlib>

namespace oasis {
namespace {
std::string glString(GLenum name) {
    const GLubyte* text = glGetString(name);
    return text ? reinterpret_cast<const char*>(text) : "";
}

// UNMASKED_VENDOR_WEBGL (0x9245) or UNMASKED_RENDERER_WEBGL (0x9246), "" without the extension.
std::string unmasked(int which) {
    char* text = reinterpret_cast<char*>(EM_ASM_INT({
        var ext = GLctx.getExtension('WEBGL_debug_renderer_info');
        var s = ext ? String(GLctx.getParameter($0)) : '';
        var n = lengthBytesUTF8(s) + 1;
        var p = _malloc(n);
        stringToUTF8(s, p, n);  // no commas outside parentheses: EM_ASM is a macro
        return p;
    }, which));
    std::string out = text ? text : "";
    std::free(text);
    return out;
}
bool gDebugMode = false;
}  // namespace

std::string ContextInfo::summary() const { return version + " on " + renderer; }

ContextInfo queryContextInfo() {
    ContextInfo info;
    info.version = glString(GL_VERSION);
    std::string vendor = unmasked(0x9245), renderer = unmasked(0x9246);
    info.vendor = vendor.empty() ? glString(GL_VENDOR) : vendor;
    info.renderer = renderer.empty() ? glString(GL_RENDERER) : renderer;
    info.glslVersion = glString(GL_SHADING_LANGUAGE_VERSION);
    glGetIntegerv(GL_MAJOR_VERSION, &info.major);
    glGetIntegerv(GL_MINOR_VERSION, &info.minor);
    return info;
}

void installDebugOutput() {}  // WebGL has no KHR_debug; the browser's console shows GL errors
void setGlDebugMode(bool on) { gDebugMode = on; }
bool glDebugMode() { return gDebugMode; }
GlDebugCounts glDebugCounts() { return {}; }
std::string glDebugSummary() { return "oasis: --gl-debug: not available in the browser"; }
void setGlErrorStop(GlErrorStop) {}
std::string headlessDisplayDescription() { return "the page's WebGL 2 canvas"; }

// The page has one WebGL 2 context, the canvas's: what a command makes its own context for (each
// `oasis check` case) draws on that one, and the state the page's frame loop left bound is put
// back when the command is done, so the next animation frame finds its own objects.
namespace {
struct PageGlState {
    GLint drawFramebuffer = 0, readFramebuffer = 0, program = 0, vertexArray = 0, arrayBuffer = 0, activeTexture = 0;
    GLint viewport[4] = {}, scissorBox[4] = {};
    GLboolean flags[6] = {};
};
const GLenum kPageFlags[6] = {GL_DEPTH_TEST, GL_STENCIL_TEST, GL_BLEND, GL_CULL_FACE, GL_SCISSOR_TEST, GL_POLYGON_OFFSET_FILL};
PageGlState* gSaved = nullptr;  // the outermost context's: contexts nest (the check's driver report, a case)
int gDepth = 0;
}  // namespace

NoGlxContextForEpoxy::NoGlxContextForEpoxy() {}  // no GLX in a page
NoGlxContextForEpoxy::~NoGlxContextForEpoxy() {}

HeadlessContext::HeadlessContext(MaxGlVersion max) {
    if (emscripten_webgl_get_current_context() == 0)
        throw std::runtime_error("the page has no WebGL 2 context");
    if (!max.es)
        throw std::runtime_error("a browser has WebGL 2 (OpenGL ES 3.0) only, no desktop OpenGL context");
    if (gDepth++ > 0) return;
    gSaved = new PageGlState;
    PageGlState& s = *gSaved;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &s.drawFramebuffer);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &s.readFramebuffer);
    glGetIntegerv(GL_CURRENT_PROGRAM, &s.program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &s.vertexArray);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &s.arrayBuffer);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &s.activeTexture);
    glGetIntegerv(GL_VIEWPORT, s.viewport);
    glGetIntegerv(GL_SCISSOR_BOX, s.scissorBox);
    for (int i = 0; i < 6; ++i) s.flags[i] = glIsEnabled(kPageFlags[i]);
}

HeadlessContext::~HeadlessContext() {
    if (--gDepth > 0 || !gSaved) return;
    const PageGlState& s = *gSaved;
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(s.drawFramebuffer));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(s.readFramebuffer));
    glUseProgram(GLuint(s.program));
    glBindVertexArray(GLuint(s.vertexArray));
    glBindBuffer(GL_ARRAY_BUFFER, GLuint(s.arrayBuffer));
    glActiveTexture(GLenum(s.activeTexture));
    glViewport(s.viewport[0], s.viewport[1], s.viewport[2], s.viewport[3]);
    glScissor(s.scissorBox[0], s.scissorBox[1], s.scissorBox[2], s.scissorBox[3]);
    for (int i = 0; i < 6; ++i) (s.flags[i] ? glEnable : glDisable)(kPageFlags[i]);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilMask(0xFF);
    delete gSaved;
    gSaved = nullptr;
}

}  // namespace oasis
