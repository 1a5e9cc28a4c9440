// The web build's half of context/gl_context.h: the page owns the WebGL 2 context (web_app.cpp),
// so only the queries are here. GL_RENDERER in a browser is masked ("WebKit WebGL"); the driver's
// own strings come from WEBGL_debug_renderer_info where the browser offers it.
#include "context/gl_context.h"

#include <emscripten.h>
#include <epoxy/gl.h>

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

}  // namespace oasis
