// The browser's app: a WebGL 2 canvas from emscripten's GLFW and, on it, the native window's own
// WindowApp (window/window_app.h: panel, keys, inspector, live comparison), whose frame() the
// page's main loop calls; and what the page's hooks (web_api.cpp) ask of it.
#pragma once
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "cli/options.h"
#include "window/window_app.h"

struct GLFWwindow;

namespace oasis::web {

// Writes `message` into the page (the #status element) and to the console.
void showPageError(const std::string& message);

class WebApp {
public:
    explicit WebApp(const Options& options) : options_(options) {}
    // Opens the WebGL 2 canvas and the window app; false (with the reason on the page) when it cannot.
    bool start();
    void frame();  // one main-loop iteration: the window app's frame at the canvas's size

    // The page's hooks (web_api.cpp): the final frame of a pipeline at the page's size, as the
    // native `render` writes it, into a PNG in the page's file system.
    bool writeFinalPng(PipelineKind kind, const std::string& path);
    // `oasis probe --at X,Y --json`'s object for the page's options' frame (x, y from the top left).
    std::string probeJson(PipelineKind kind, int x, int y);
    // What the panel's radio buttons and view list choose (as Tab and 1..9 do).
    void setPipeline(PipelineKind kind);
    bool setView(const std::string& view);  // false for a name that is no view
    std::string capabilityJson();  // the context, every feature and the fallbacks
    // What the window app shows now: {"pipeline", "gbuffer", "view", "paused", "panel", "compare", "pins"}.
    std::string windowStateJson();
    long framesDrawn() const { return app_ ? app_->state().counts.framesDrawn : 0; }

private:
    SceneSettings optionsScene();
    RenderSession& session() { return app_->session(); }
    Options options_;
    GLFWwindow* window_ = nullptr;
    std::unique_ptr<WindowApp> app_;
    std::chrono::steady_clock::time_point last_;
};

}  // namespace oasis::web
