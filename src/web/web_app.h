// The browser app's state: one RenderSession on the page's WebGL 2 context, what the panel and the
// page's hooks (web_api.cpp) change, and the frame the main loop draws.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "cli/options.h"
#include "commands/session.h"

struct GLFWwindow;

namespace oasis::web {

// Writes `message` into the page (the #status element) and to the console.
void showPageError(const std::string& message);

class WebApp {
public:
    explicit WebApp(const Options& options) : options_(options), pipeline_(options.pipeline), view_(options.view) {}
    // Opens the WebGL 2 canvas and the session; false (with the reason on the page) when it cannot.
    bool start();
    void frame();  // one main-loop iteration: the scene, the view, the panel

    // The page's hooks (web_api.cpp): the final frame of a pipeline at the current size, as the
    // native `render` writes it, into a PNG in the page's file system.
    bool writeFinalPng(PipelineKind kind, const std::string& path);
    // `oasis probe --at X,Y --json`'s object for the page's options' frame (x, y from the top left).
    std::string probeJson(PipelineKind kind, int x, int y);
    void setPipeline(PipelineKind kind) { pipeline_ = kind; }
    void setView(const std::string& view) { view_ = view; }
    std::string capabilityJson() const;  // the context, every feature and the fallbacks
    int framesDrawn() const { return frames_; }
    RenderSession& session() { return *session_; }

private:
    void drawPanel();
    SceneSettings optionsScene() const;
    Options options_;
    PipelineKind pipeline_;
    std::string view_;
    GLFWwindow* window_ = nullptr;
    std::unique_ptr<RenderSession> session_;
    int frames_ = 0;
    double startSeconds_ = 0.0;
    bool paused_ = false;
    std::vector<std::string> webFallbacks_;  // what the page changed for its browser, and why
};

}  // namespace oasis::web
