// The window state's small verbs: the loop's summary, the configuration in and out of the scene,
// the panel's message, shader reload and RenderDoc capture requests.
#include "window/window_state.h"

#include <algorithm>
#include <cstdio>

#include "frame/encoding_error.h"
#include "gl/frame_capture.h"

namespace oasis {
namespace window {

std::string loopSummary(const WindowCounts& counts) {
    std::string text;
    for (const std::string& label : counts.loopOrder) {
        std::vector<double> v = counts.loopMs.at(label);
        std::sort(v.begin(), v.end());
        char part[128];
        std::snprintf(part, sizeof(part), "%s%s %.2f (%zu frames)", text.empty() ? "" : ", ", label.c_str(),
                      v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]), v.size());
        text += part;
    }
    return text.empty() ? "none" : text;
}

std::string loopLabel(const WindowState& state) {
    const Configuration& shown = state.lastDrawn ? *state.lastDrawn : state.chosen;
    std::string label = state.comparison.mode == CompareMode::Off ? std::string(pipelineName(shown.pipeline))
                                                                 : compareModeName(state.comparison.mode);
    if (shown.view != "final") label += " view " + shown.view;
    if (state.inspector.sectionOpen) label += " inspector";
    return label;
}

Configuration currentConfiguration(const WindowState& state, const SceneSettings& scene) {
    Configuration config = state.chosen;
    config.lightCount = scene.lights.count;
    config.lightsPath = scene.lights.path;
    config.reflections = scene.water.reflections;
    config.vegetation = scene.vegetation.enabled;
    return config;
}

void restoreConfiguration(const Configuration& config, WindowState& state, SceneSettings& scene) {
    state.chosen = config;
    scene.lights.count = config.lightCount;
    scene.lights.path = config.lightsPath;
    scene.water.reflections = config.reflections;
    scene.vegetation.enabled = config.vegetation;
}

void choosePipeline(WindowState& state, PipelineKind kind) {
    if (state.chosen.pipeline == kind) return;
    state.chosen.pipeline = kind;
    ++state.counts.pipelineSwitches;
}

std::vector<std::string> viewNames() {
    std::vector<std::string> names;
    for (const DebugView& view : debugViews()) names.push_back(view.name);
    names.push_back(kOverviewName);
    for (const EncodingErrorView& view : encodingErrorViews()) names.push_back(view.name);
    return names;
}

void report(WindowState& state, const std::string& message, bool isError) {
    if (message == state.message && isError == state.messageIsError) return;
    state.message = message;
    state.messageIsError = isError;
    std::fprintf(isError ? stderr : stdout, "oasis: %s\n", message.c_str());
    std::fflush(isError ? stderr : stdout);
}

void reloadShaders(Renderer& renderer, WindowState& state) {
    ShaderLibrary& shaders = renderer.parts().shaders;
    std::vector<std::string> failures = shaders.reloadAll();
    state.message.clear();  // a reload always reports, even when it repeats the last message
    if (failures.empty()) {
        report(state, "shaders reloaded: " + std::to_string(shaders.programCount()) + " programs rebuilt from " +
                          shaders.directory(), false);
        return;
    }
    report(state, "reload: " + std::to_string(failures.size()) + " of " + std::to_string(shaders.programCount()) +
                      " programs failed and keep their previous version; the first: " + failures.front(), true);
    for (size_t i = 1; i < failures.size(); ++i) std::fprintf(stderr, "oasis: reload: %s\n", failures[i].c_str());
}

// F9 or the panel's button: RenderDoc captures the next presented frame (scene, view and panel);
// its path is reported once written. Without RenderDoc the panel says why nothing happens.
void requestCapture(WindowState& state) {
    std::string why;
    if (!gl::renderDocLoaded(&why)) {
        report(state, "capture: " + why, true);
        return;
    }
    state.capturesBefore = gl::renderDocCaptures().size();
    gl::triggerWindowCapture();
    report(state, "capture: RenderDoc captures the next frame", false);
}

void reportNewCapture(WindowState& state) {
    if (!state.capturesBefore) return;
    std::vector<std::string> captures = gl::renderDocCaptures();
    if (captures.size() <= *state.capturesBefore) return;
    report(state, "RenderDoc capture: " + captures.back(), false);
    state.capturesBefore.reset();
}

}  // namespace window
}  // namespace oasis
