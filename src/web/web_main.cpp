// The browser's oasis: the ES 3.0 tier's RenderSession in a WebGL 2 canvas (emscripten's GLFW),
// driven by emscripten_set_main_loop, which calls the native window's WindowApp::frame (web_app.cpp),
// and the page's hooks (web_api.cpp). Options come from the page's URL query, parsed by the native command line parser.
#include <emscripten.h>
#define GLFW_INCLUDE_ES3  // GLFW includes <GLES3/gl3.h>, not desktop <GL/gl.h>
#include <GLFW/glfw3.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>


#include "web/web_app.h"

namespace oasis::web {
namespace {
WebApp* gApp = nullptr;

// "?size=640x360&pipeline=forward" → {"--size", "640x360", "--pipeline", "forward"}.
std::vector<std::string> queryArguments() {
    char* query = reinterpret_cast<char*>(EM_ASM_INT({
        var s = typeof location === 'undefined' ? '' : location.search.substring(1);
        var n = lengthBytesUTF8(s) + 1;
        var p = _malloc(n);
        stringToUTF8(s, p, n);  // no commas outside parentheses: EM_ASM is a macro
        return p;
    }));
    std::string text = query ? query : "";
    std::free(query);
    std::vector<std::string> arguments;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('&', start);
        if (end == std::string::npos) end = text.size();
        std::string pair = text.substr(start, end - start);
        size_t eq = pair.find('=');
        std::string key = pair.substr(0, eq);
        if (!key.empty() && key != "test") {
            arguments.push_back("--" + key);
            if (eq != std::string::npos) arguments.push_back(pair.substr(eq + 1));
        }
        start = end + 1;
    }
    return arguments;
}

void frame() { gApp->frame(); }
}  // namespace

WebApp& app() { return *gApp; }
}  // namespace oasis::web

int main() {
    using namespace oasis;
    // The same tier as `oasis render --api gles --force gles30`: WebGL 2 is OpenGL ES 3.0.
    std::vector<std::string> arguments = {"render", "--api", "gles", "--force", "gles30", "--size", "960x540"};
    for (const std::string& a : web::queryArguments()) arguments.push_back(a);
    ParseResult parsed = parseCommandLine(arguments);
    if (!parsed.ok) {
        web::showPageError("bad page options: " + parsed.error);
        return 1;
    }
    static web::WebApp app(parsed.options);
    web::gApp = &app;
    if (!app.start()) return 1;
    emscripten_set_main_loop(web::frame, 0, false);
    return 0;
}
