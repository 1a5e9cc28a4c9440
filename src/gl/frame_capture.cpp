// Frame terminators and RenderDoc's in-application API (found with dlopen RTLD_NOLOAD).
#include "gl/frame_capture.h"

#include <dlfcn.h>
#include <epoxy/gl.h>

#include <cstdint>
#include <string>

namespace oasis::gl {
namespace {

// The leading part of RenderDoc's API table (renderdoc_app.h, RENDERDOC_API_1_1_2 and later), as
// far as the entries oasis calls: each entry is one function pointer, in the header's order. The
// ones oasis never calls are kept only as slots.
struct RenderDocApi {
    void* getApiVersion;
    void* captureOptions[4];       // Set/GetCaptureOption U32/F32
    void* keysAndOverlay[4];       // SetFocusToggleKeys, SetCaptureKeys, Get/MaskOverlayBits
    void* removeHooks;
    void* unloadCrashHandler;
    void* setCaptureFilePathTemplate;
    void* getCaptureFilePathTemplate;
    uint32_t (*getNumCaptures)();
    uint32_t (*getCapture)(uint32_t index, char* filename, uint32_t* pathLength, uint64_t* timestamp);
    void (*triggerCapture)();
    void* isTargetControlConnected;
    void* launchReplayUi;
    void* setActiveWindow;
    void (*startFrameCapture)(void* device, void* window);
    uint32_t (*isFrameCapturing)();
    uint32_t (*endFrameCapture)(void* device, void* window);
};
constexpr int kApiVersion_1_1_2 = 10102;  // eRENDERDOC_API_Version_1_1_2: the table above
using GetApi = int (*)(int version, void** api);

bool gTerminators = false;
bool gFrameOpen = false;
bool gCapturing = false;
int gArmedCaptures = 0;

RenderDocApi* renderDoc(std::string* why) {
    static RenderDocApi* api = nullptr;
    static std::string reason;
    static bool looked = false;
    if (!looked) {
        looked = true;
        // Only a library RenderDoc already injected: loading it here would hook nothing.
        void* library = dlopen("librenderdoc.so", RTLD_NOW | RTLD_NOLOAD);
        if (!library) {
            reason = "not running under RenderDoc (librenderdoc.so is not loaded in this process; start oasis "
                     "with `renderdoccmd capture -w -d DIR oasis ...` or from RenderDoc's launch dialog)";
        } else if (auto getApi = reinterpret_cast<GetApi>(dlsym(library, "RENDERDOC_GetAPI")); !getApi) {
            reason = "librenderdoc.so is loaded but has no RENDERDOC_GetAPI";
        } else if (!getApi(kApiVersion_1_1_2, reinterpret_cast<void**>(&api)) || !api) {
            api = nullptr;
            reason = "RenderDoc refused its in-application API version 1.1.2";
        }
    }
    if (!api && why) *why = reason;
    return api;
}

// The tracer's own glFrameTerminatorGREMEDY, where a tracer is preloaded into this process.
// apitrace's egltrace.so exports it but, on a desktop GL context made through EGL, does not list
// GL_GREMEDY_frame_terminator in glGetStringi (measured: docs/captures.md), so the extension
// check alone would miss it. Only a tracer's symbol counts: GLVND's libGL.so.1 exports a stub too.
using Terminator = void (*)();
Terminator tracerTerminator() {
    static Terminator found = [] {
        void* symbol = dlsym(RTLD_DEFAULT, "glFrameTerminatorGREMEDY");
        Dl_info info{};
        if (!symbol || !dladdr(symbol, &info) || !info.dli_fname) return Terminator(nullptr);
        std::string library = info.dli_fname;
        bool tracer = library.find("apitrace") != std::string::npos || library.find("renderdoc") != std::string::npos;
        return tracer ? reinterpret_cast<Terminator>(symbol) : Terminator(nullptr);
    }();
    return found;
}

void terminate() {
    // Asked once: headless commands have one context, and the extension list is long to scan.
    static const bool listed = epoxy_has_gl_extension("GL_GREMEDY_frame_terminator");
    if (Terminator tracer = tracerTerminator()) tracer();
    else if (listed) glFrameTerminatorGREMEDY();
}

}  // namespace

void setFrameTerminators(bool on) { gTerminators = on; }

void endFrame() {
    if (gCapturing) {  // before the terminator: RenderDoc may treat that as the frame's end too
        renderDoc(nullptr)->endFrameCapture(nullptr, nullptr);
        gCapturing = false;
    }
    if (gTerminators) terminate();
    gFrameOpen = false;
}

void beginFrame() {
    if (gFrameOpen || gCapturing) endFrame();
    gFrameOpen = true;
    if (gArmedCaptures > 0) {
        if (RenderDocApi* api = renderDoc(nullptr)) {
            api->startFrameCapture(nullptr, nullptr);  // the current context
            gCapturing = true;
        }
        --gArmedCaptures;
    }
}

bool renderDocLoaded(std::string* why) { return renderDoc(why) != nullptr; }

void armCaptures(int frames) { gArmedCaptures = frames; }

void triggerWindowCapture() {
    if (RenderDocApi* api = renderDoc(nullptr)) api->triggerCapture();
}

std::vector<std::string> renderDocCaptures() {
    std::vector<std::string> paths;
    RenderDocApi* api = renderDoc(nullptr);
    if (!api) return paths;
    for (uint32_t i = 0, n = api->getNumCaptures(); i < n; ++i) {
        uint32_t length = 0;
        if (!api->getCapture(i, nullptr, &length, nullptr) || length == 0) continue;
        std::string path(length, '\0');
        api->getCapture(i, path.data(), &length, nullptr);
        path.resize(path.find('\0') == std::string::npos ? path.size() : path.find('\0'));
        paths.push_back(path);
    }
    return paths;
}

}  // namespace oasis::gl
