// The window's state shared by its parts (window_app.cpp's loop, the panel, the keys and mouse,
// the drawing of a configuration): what is chosen, what the inspector holds, what is counted.
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands/probe_report.h"
#include "commands/session.h"
#include "window/window_compare.h"
#include "debug/debug_views.h"
#include "debug/view_controls.h"
#include "frame/pixel_probe.h"

struct GLFWwindow;

namespace oasis {
namespace window {

// What the window draws, as the keys and the panel choose it: everything that decides which
// shader programs a frame needs, so going back to a configuration that drew draws again.
struct Configuration {
    PipelineKind pipeline = PipelineKind::Deferred;
    size_t layoutIndex = 0;  // into gbufferLayouts()
    size_t depthIndex = 0;   // into depthConventions(): the one asked for
    std::string view = "final";
    WaterScene waterScene = WaterScene::Direct;  // what the views show at water pixels (M)
    // Scene settings that pick program variants: the light path's, the mirrored ones, the plants'.
    int lightCount = 0;
    std::optional<LightsPath> lightsPath;
    bool reflections = true;
    bool vegetation = true;

    bool operator==(const Configuration& o) const {
        return pipeline == o.pipeline && layoutIndex == o.layoutIndex && depthIndex == o.depthIndex &&
               view == o.view && waterScene == o.waterScene && lightCount == o.lightCount && lightsPath == o.lightsPath &&
               reflections == o.reflections && vegetation == o.vegetation;
    }
    bool operator!=(const Configuration& o) const { return !(*this == o); }
    std::string describe() const {
        return std::string(pipelineName(pipeline)) + ", " + gbufferLayouts()[layoutIndex].name + " G-buffer, " +
               depthConventions()[depthIndex].name + " depth, view " + view + ", " + std::to_string(lightCount) +
               " lights";
    }
};

// A probe of one frame: in a comparison, of the side shown at the pixel ("B: deferred, compact"; both
// sides in a difference); empty for the window's single frame.
struct SideProbe {
    std::string side;
    PixelProbe probe;
};

// The inspector: the probe under the cursor and the pinned ones, and the view controls.
struct Inspector {
    std::optional<glm::ivec2> hovered;   // the framebuffer pixel under the cursor, 0,0 top left
    std::vector<SideProbe> hoveredProbes;
    std::vector<glm::ivec2> pinned;      // numbered on screen in this order
    std::vector<std::vector<SideProbe>> pinnedProbes;  // one entry per pin, each of its sides
    bool frozen = false;                 // F: the pins keep the values they had (new pins are read once)
    double frozenAt = 0.0;               // the clock when they were frozen
    // I: each pin's shading and history (the hovered pixel's when nothing is pinned), computed once
    // for the frame of that moment, as `oasis probe --shading --history` reports them.
    bool deepRequested = false;
    struct Deep {
        size_t pin;        // its number - 1; the hovered pixel's when no pin was made
        std::string side;
        double timeSeconds;
        ProbeReport report;
    };
    std::vector<Deep> deep;
    static constexpr size_t kHovered = size_t(-1);  // Deep::pin of the hovered pixel's
    bool printHovered = false;           // P: print the next hovered probe
    int channelChoice = 0;               // 0: the view's own colours; else 1 + ViewChannel
    bool fitRange = true;
    float range[2] = {0.0f, 1.0f};
    bool overlayNan = true, overlayInfinity = true, overlayNegative = false;
    float exposureStops = 0.0f;
    std::optional<ValueStatistics> statistics;  // of the last single view drawn
    bool sectionOpen = false;  // the panel shows the inspector this frame: only then are counts read
    std::vector<std::string> overviewCounts;    // the overview's tiles' counts, while it is shown
    static constexpr size_t kMaxPins = 9;

    ViewControls controls() const {
        ViewControls c;
        if (channelChoice > 0) c.channel = ViewChannel(channelChoice - 1);
        if (channelChoice > 0 && !fitRange && range[0] < range[1]) c.range = std::pair{double(range[0]), double(range[1])};
        c.overlay = (overlayNan ? kOverlayNan : 0u) | (overlayInfinity ? kOverlayInfinity : 0u) |
                    (overlayNegative ? kOverlayNegative : 0u);
        return c;
    }
};

// What happened in the window, printed when it closes (the window tests read it).
struct WindowCounts {
    long framesDrawn = 0, pipelineSwitches = 0, resizes = 0, minimised = 0, switchesUndone = 0;
    // Wall ms of each whole loop iteration (frame(s), views, panel, swap, glFinish), by what it
    // showed: the cost of the comparison modes against single frames (docs/window_cost.sh).
    std::map<std::string, std::vector<double>> loopMs;
    std::vector<std::string> loopOrder;
};

struct WindowState {
    Configuration chosen;                      // what the keys and the panel ask for
    std::optional<Configuration> lastDrawn;    // the last configuration whose frame was drawn
    bool paused = false;
    bool freeCamera = false;
    bool panelShown = true;
    bool overlayShown = true;   // the pipeline and frame time in the corner (O), whether the panel shows or not
    std::string panelGeometry;  // the panel's rectangle and widest line, printed when it changes
    double frameMs = 0.0, smoothedMs = 0.0;
    std::string message;  // last reload result or error, shown in the panel
    bool messageIsError = false;
    std::vector<std::string> fallbacks;  // the session's fallbacks (printed once at start-up too)
    Inspector inspector;
    WindowComparison comparison;
    std::unique_ptr<Renderer> sideB;  // the comparison's second renderer, made when first needed
    bool draggingDivider = false;
    std::string errorViewSummary;  // an encoding-error view's numbers, for the panel
    WindowCounts counts;
    std::optional<size_t> capturesBefore;  // F9: RenderDoc's capture count when the capture was asked for
};

// window_state.cpp: the state's small verbs.
std::string loopSummary(const WindowCounts& counts);
std::string loopLabel(const WindowState& state);
// The chosen configuration with the scene's own settings in it, and back.
Configuration currentConfiguration(const WindowState& state, const SceneSettings& scene);
void restoreConfiguration(const Configuration& config, WindowState& state, SceneSettings& scene);
void choosePipeline(WindowState& state, PipelineKind kind);
std::vector<std::string> viewNames();
// Shows `message` in the panel and prints it (once, however many frames repeat it): errors to
// stderr, results to stdout, each line starting "oasis: ".
void report(WindowState& state, const std::string& message, bool isError);
void reloadShaders(Renderer& renderer, WindowState& state);
void requestCapture(WindowState& state);
void reportNewCapture(WindowState& state);

// window_input.cpp: keys, mouse and the free camera.
void handleKeys(GLFWwindow* window, int key, int action, Renderer& renderer, WindowState& state,
                SceneSettings& scene);
void handleInspectorMouse(GLFWwindow* window, Inspector& inspector, WindowComparison& comparison, bool& dragging);
void moveFreeCamera(GLFWwindow* window, CameraPose& pose, float seconds);

// window_panel.cpp and window_panel_sections.cpp: the ImGui panel and what is drawn over the frame.
void drawPanel(Renderer& renderer, SceneSettings& scene, WindowState& state);
void drawComparePanel(WindowState& state);
void drawInspectorPanel(WindowState& state, double clockSeconds);  // the clock: when pins are frozen
void drawPinMarkers(GLFWwindow* window, const Inspector& inspector);
void drawCompareLabels(GLFWwindow* window, const WindowComparison& c);
void drawStatusOverlay(GLFWwindow* window, const WindowState& state);

// A frame the window drew this loop: its renderer, and its side's name in a comparison ("" alone).
struct DrawnSide {
    Renderer* renderer;
    std::string name;
};

// window_probes.cpp: the inspector's probes of what is shown, read from the side that drew each pixel.
std::vector<DrawnSide> sidesShownAt(glm::ivec2 pixel, const std::vector<DrawnSide>& sides, const WindowComparison& c,
                                    int width);
// I: the pins' (or the hovered pixel's) shading and history, printed as `probe --shading --history
// --json` prints them ("oasis: probe in depth #N {...}"). Renders frames: call it before the
// frame that is shown is drawn (or read what was shown first).
void probeInDepthWhenAsked(Inspector& inspector, const SceneSettings& scene, const std::vector<DrawnSide>& sides,
                           const WindowComparison& c, int width, int height);
// The hovered pixel's and the pins' probes (frozen pins keep theirs); P prints the hovered one.
void probeShownPixels(Inspector& inspector, const std::vector<DrawnSide>& sides, const WindowComparison& c, int width,
                      int height);

// Each pinned probe as one JSON line after "oasis: WHAT #N " (F prints them when it freezes and thaws).
void printPins(const Inspector& inspector, const std::string& what);

// window_draw.cpp: one frame of the chosen configuration, single or compared, and its inspection.
bool drawChosen(RenderSession& session, SceneSettings& scene, WindowState& state, int width, int height);

}  // namespace window
}  // namespace oasis
