// A PNG's provenance (commands/provenance.h): the table of keys, what this process writes under
// them, and reading them back.
#include "commands/provenance.h"

#include <optional>

#include "cli/input_domains.h"
#include "cli/option_rules.h"
#include "cli/options.h"
#include "cli/scene_arguments.h"
#include "context/gl_context.h"

namespace oasis {
namespace {

// A command line longer than this is cut (a chunk holds at most kMaxPngTextBytes).
constexpr size_t kMaxCommandBytes = 8192;

// render's options that change a view as drawn, each written when it is not at its default and
// not idle for the view (cli/option_rules.h: --water-scene on the final view changes nothing).
struct ViewArgument {
    const char* flag;
    std::string (*value)(const Options& options);  // "" at its default
};
const ViewArgument kViewArguments[] = {
    {"--view-exposure", [](const Options& o) { return o.viewExposure != 0.0f ? exactNumber(o.viewExposure, true) : ""; }},
    {"--channel",
     [](const Options& o) {
         return o.viewControls.channel ? std::string(viewChannelName(*o.viewControls.channel)) : std::string();
     }},
    {"--range",
     [](const Options& o) {
         if (!o.viewControls.range) return std::string();
         return exactNumber(o.viewControls.range->first) + "," + exactNumber(o.viewControls.range->second);
     }},
    {"--overlay",
     [](const Options& o) {
         return o.viewControls.overlay != ViewControls{}.overlay ? overlayNames(o.viewControls.overlay) : "";
     }},
    {"--stencil-view",
     [](const Options& o) { return o.stencilView ? std::string(stencilViewPathName(*o.stencilView)) : std::string(); }},
    {"--water-scene",
     [](const Options& o) {
         return o.waterScene != WaterScene::Direct ? std::string(waterSceneName(o.waterScene)) : std::string();
     }},
    {"--stop-before", [](const Options& o) { return o.stopBefore; }},
};

bool idleFor(const Options& options, const char* flag) {
    for (const OptionRule& rule : optionRules())
        if (std::string(rule.flag) == flag && rule.idle(options)) return true;
    return false;
}

std::string viewArguments(const Options& options) {
    if (options.command != Command::Render) return {};  // the other commands draw their views plainly
    std::vector<std::string> arguments;
    for (const ViewArgument& row : kViewArguments) {
        std::string value = row.value(options);
        if (value.empty() || idleFor(options, row.flag)) continue;
        arguments.push_back(row.flag);
        arguments.push_back(value);
    }
    return joinArguments(arguments);
}

}  // namespace

const std::vector<ProvenanceKey>& provenanceKeys() {
    static const std::vector<ProvenanceKey> keys = {
        {"oasis:version", &Provenance::version, false},
        {"oasis:options", &Provenance::options, true},
        {"oasis:driver-options", &Provenance::driverOptions, false},
        {"oasis:view", &Provenance::view, true},
        {"oasis:view-options", &Provenance::viewOptions, false},
        {"oasis:pipeline", &Provenance::pipeline, true},
        {"oasis:legend", &Provenance::legend, true},
        {"oasis:renderer", &Provenance::renderer, false},
        {"oasis:gl-version", &Provenance::glVersion, false},
        {"oasis:command", &Provenance::command, false},
    };
    return keys;
}

Provenance pictureProvenance(const Options& options, const std::string& view, const std::string& pipeline,
                             int imageHeight, int frameHeight) {
    Provenance provenance;
    provenance.version = oasisVersion();
    provenance.options = joinArguments(sceneArguments(options.scene, SceneArgumentKind::Picture));
    provenance.driverOptions = joinArguments(sceneArguments(options.scene, SceneArgumentKind::Driver));
    provenance.view = view;
    provenance.viewOptions = viewArguments(options);
    provenance.pipeline = pipeline;
    provenance.legend = imageHeight > frameHeight ? "on, frame height " + std::to_string(frameHeight) : "off";
    ContextInfo context = queryContextInfo();
    provenance.renderer = context.renderer;
    provenance.glVersion = context.version;
    provenance.command = options.commandLine;
    if (provenance.command.size() > kMaxCommandBytes)
        provenance.command = provenance.command.substr(0, kMaxCommandBytes) + " ... (" +
                             std::to_string(options.commandLine.size() - kMaxCommandBytes) + " bytes cut)";
    return provenance;
}

std::vector<PngText> provenanceTexts(const Provenance& provenance) {
    std::vector<PngText> texts;
    for (const ProvenanceKey& key : provenanceKeys()) texts.push_back({key.key, provenance.*key.field});
    return texts;
}

bool readProvenance(const PngTexts& texts, Provenance& provenance, std::string& why) {
    provenance = Provenance{};
    bool any = false;
    std::string missing;
    for (const ProvenanceKey& key : provenanceKeys()) {
        const PngText* text = texts.find(key.key);
        any = any || text;
        if (text) provenance.*key.field = text->text;
        else if (key.required) missing += (missing.empty() ? "" : ", ") + std::string(key.key);
    }
    if (any && missing.empty()) return true;
    why = any ? "its oasis text chunks lack " + missing
              : "no oasis text chunks (written by another program, by an oasis from before provenance, or stripped)";
    if (!texts.ignored.empty()) why += "; a text chunk was left out: " + texts.ignored.front();
    return false;
}

}  // namespace oasis
