// The rules for options that would be idle (cli/option_rules.h). A row is added when an option is
// found to do nothing in some circumstance; the tests render each row's example to hold it true.
#include "cli/option_rules.h"

#include <algorithm>
#include <cstdlib>

#include "cli/options.h"
#include "debug/debug_view_pass.h"
#include "debug/debug_views.h"
#include "frame/encoding_error.h"

namespace oasis {
namespace {

bool renderOrProbe(const Options& o) { return o.command == Command::Render || o.command == Command::Probe; }
bool forwardOnly(const Options& o) { return renderOrProbe(o) && o.pipeline == PipelineKind::Forward; }
const DebugView* singleView(const Options& o) { return o.command == Command::Render ? findDebugView(o.view) : nullptr; }
bool reflectionReduced(const Options& o) { return o.scene.water.reflectionDivisor != 1; }

std::string reflectionResolutionOf(const Options& o) {
    return reflectionResolutionName(o.scene.water.reflectionDivisor);
}

}  // namespace

const std::vector<OptionRule>& optionRules() {
    static const std::vector<OptionRule> rules = {
        {"--reflection-plant-cull", RuleOutcome::Note,
         [](const Options& o) {
             return o.scene.work.mirroredPlantCull != MirroredPlantCull::Off &&
                    (!o.scene.water.reflections || reflectionReduced(o) || !o.scene.vegetation.enabled);
         },
         [](const Options& o) -> std::string {
             std::string why = !o.scene.water.reflections     ? "--reflections off draws no mirrored plants"
                               : !o.scene.vegetation.enabled ? "--vegetation off draws no plants"
                                                              : "at --reflection-resolution " + reflectionResolutionOf(o) +
                                                                    " the upsample's taps reach past the water's edge, "
                                                                    "so plant images on land may show: the cull runs "
                                                                    "at full resolution only";
             return "--reflection-plant-cull: no plants are culled (" + why + ")";
         },
         "--reflection-plant-cull on --reflection-resolution half", "--reflection-resolution half"},
        {"--reflection-resolution", RuleOutcome::Note,
         [](const Options& o) { return !o.scene.water.reflections && reflectionReduced(o); },
         [](const Options&) -> std::string {
             return "--reflection-resolution: no mirrored scene is drawn (--reflections off): the water reflects the "
                    "sky alone, at full resolution";
         },
         "--reflection-resolution quarter --reflections off", "--reflections off"},
        {"--shadow-quality", RuleOutcome::Note, [](const Options& o) { return !o.scene.shadows.enabled; },
         [](const Options& o) -> std::string {
             return "--shadow-quality " + o.scene.shadows.quality + ": no shadow maps are drawn (--shadows off)";
         },
         "--shadow-quality high --shadows off", "--shadows off"},
        {"--vegetation-density", RuleOutcome::Note, [](const Options& o) { return !o.scene.vegetation.enabled; },
         [](const Options&) -> std::string { return "--vegetation-density: no plants are placed (--vegetation off)"; },
         "--vegetation-density 3 --vegetation off", "--vegetation off"},
        {"--wind", RuleOutcome::Note, [](const Options& o) { return !o.scene.vegetation.enabled; },
         [](const Options&) -> std::string { return "--wind: no plants are drawn to bend (--vegetation off)"; },
         "--wind 3 --vegetation off", "--vegetation off"},
        {"--billboards", RuleOutcome::Note, [](const Options& o) { return !o.scene.vegetation.enabled; },
         [](const Options&) -> std::string { return "--billboards: no plant billboards are drawn (--vegetation off)"; },
         "--billboards whole --vegetation off", "--vegetation off"},
        {"--depth-read", RuleOutcome::Note,
         [](const Options& o) { return o.scene.gbuffer != "compact" || forwardOnly(o); },
         [](const Options& o) -> std::string {
             return forwardOnly(o) ? "--depth-read: the forward pipeline has no deferred lighting to read depth"
                                   : "--depth-read: the " + o.scene.gbuffer +
                                         " layout stores positions, so its lighting reads no depth (compact only)";
         },
         "--depth-read copy --gbuffer standard", "--gbuffer standard"},
        {"--light-method", RuleOutcome::Note, forwardOnly,
         [](const Options&) -> std::string {
             return "--light-method: the forward pipeline adds every light in its own shading (the method is the "
                    "deferred pipeline's)";
         },
         "--light-method tiled --pipeline forward --lights 16 --hour 21", "--pipeline forward --lights 16 --hour 21"},
        {"--view-exposure", RuleOutcome::Refuse,
         [](const Options& o) {
             const DebugView* view = findDebugView(o.view);
             return o.viewExposure != 0.0f && o.view != kOverviewName && (!view || view->remapDefine != "VIEW_HDR");
         },
         [](const Options& o) -> std::string {
             return "--view-exposure scales the HDR views (radiance, reflection-raw) and their overview tiles, not "
                    "--view " + o.view;
         },
         "--view-exposure 5", ""},
        {"--water-scene", RuleOutcome::Note,
         [](const Options& o) {
             const DebugView* view = singleView(o);
             return view && !readsSceneSurfaces(*view);
         },
         [](const Options& o) -> std::string {
             return "--water-scene: the " + o.view + " view shows the frame as drawn, not the G-buffer (the water "
                    "scene is for the G-buffer, depth, stencil and error views)";
         },
         "--water-scene mirrored", ""},
        {"--stencil-view", RuleOutcome::Note,
         [](const Options& o) { return o.view != "stencil" && o.view != kOverviewName; },
         [](const Options& o) -> std::string {
             return "--stencil-view: the " + o.view + " view does not show the stencil (--view stencil or overview does)";
         },
         "--stencil-view read-back", ""},
        {"--legend", RuleOutcome::Note, [](const Options& o) { return o.view == kOverviewName; },
         [](const Options&) -> std::string {
             return "--legend: the overview has no legend strip (each tile is labelled instead)";
         },
         "--legend off --view overview", "--view overview"},
        {"--size", RuleOutcome::Refuse,
         [](const Options& o) {
             auto [width, height] = overviewMinimumSize();
             return o.view == kOverviewName && (o.scene.width < width || o.scene.height < height);
         },
         [](const Options& o) -> std::string {
             auto [width, height] = overviewMinimumSize();
             return "--view overview needs at least " + std::to_string(width) + "x" + std::to_string(height) +
                    " pixels (a grid of " + std::to_string(debugViews().size()) + " tiles), got --size " +
                    std::to_string(o.scene.width) + "x" + std::to_string(o.scene.height);
         },
         "--view overview --size 2x1", ""},
    };
    return rules;
}

namespace {
// In the window every setting can be changed while it runs: an option idle at the start is not
// ignored there (the main job without a display is headless and gets the rules).
bool liveWindow(const Options& options) {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return options.command == Command::Window ||
           (options.command == Command::Default && ((x11 && *x11) || (wayland && *wayland)));
}
}  // namespace

bool applyOptionRules(const Options& options, std::vector<std::string>& notes, std::string& error) {
    if (liveWindow(options)) return true;
    for (const OptionRule& rule : optionRules()) {
        bool given = std::find(options.givenFlags.begin(), options.givenFlags.end(), rule.flag) != options.givenFlags.end();
        // The overview's size is checked whether or not --size was given (the default fits).
        if (std::string(rule.flag) == "--size") given = true;
        if (!given || !rule.idle(options)) continue;
        if (rule.outcome == RuleOutcome::Refuse) {
            error = rule.why(options);
            return false;
        }
        notes.push_back(rule.why(options));
    }
    return true;
}

}  // namespace oasis
