// The scene options' rows (cli/option_table.h): each row's text, reader, writer, widget and bench
// levels. The parser's messages are the ones scripts and tests read: keep them word for word.
#include "cli/option_table.h"

#include "cli/input_domains.h"
#include "cli/options.h"
#include "cli/scene_arguments.h"
#include "gl/driver_workarounds.h"
#include "render/depth_convention.h"
#include "render/gbuffer_layout.h"

namespace oasis {
namespace {

using Notes = std::vector<std::string>;

OptionRow named(const char* flag, const char* synopsis, const char* help) {
    OptionRow row;
    row.flag = flag;
    row.synopsis = synopsis;
    row.help = help;
    return row;
}

// A real number of the flag's input domain into a float field.
OptionRow number(const char* flag, const char* synopsis, const char* help, float& (*field)(SceneOptions&)) {
    OptionRow row = named(flag, synopsis, help);
    row.numberField = field;
    return row;
}

OptionRow twoWay(const char* flag, const char* on, const char* off, const char* help, bool& (*field)(SceneOptions&)) {
    OptionRow row = named(flag, "", help);
    row.on = on;
    row.off = off;
    row.switchField = field;
    return row;
}

OptionRow other(const char* flag, const char* synopsis, const char* help,
                bool (*read)(const std::string&, Options&, Notes&, std::string&),
                std::string (*write)(const SceneOptions&)) {
    OptionRow row = named(flag, synopsis, help);
    row.read = read;
    row.write = write;
    return row;
}

OptionRow withWidget(OptionRow row, OptionWidget widget) {
    row.widget = widget;
    return row;
}

OptionRow withBench(OptionRow row, OptionBenchKnob knob) {
    row.bench = std::move(knob);
    return row;
}

OptionRow withChoices(OptionRow row, std::vector<std::string> (*choices)()) {
    row.choices = choices;
    return row;
}

OptionWidget widget(OptionWidgetKind kind, const char* section, const char* label) {
    OptionWidget w;
    w.kind = kind;
    w.section = section;
    w.label = label;
    return w;
}
OptionWidget checkbox(const char* section, const char* label) {
    return widget(OptionWidgetKind::Checkbox, section, label);
}
OptionWidget slider(const char* section, const char* label, float low, float high, const char* format = "%.3f",
                    bool applyOnRelease = false) {
    OptionWidget w = widget(OptionWidgetKind::Slider, section, label);
    w.low = low;
    w.high = high;
    w.format = format;
    w.applyOnRelease = applyOnRelease;
    return w;
}
OptionWidget radios(const char* section, const char* label) { return widget(OptionWidgetKind::Radios, section, label); }

// The scene arguments' writer for a flag (cli/scene_arguments.h): one text form per option.
// --camera's text: the position exactly (double), the angles as the floats they are kept in.
std::string cameraText(const SceneOptions& s) {
    if (!s.camera) return std::string();
    const CameraPose& c = *s.camera;
    return exactNumber(c.position.x) + "," + exactNumber(c.position.y) + "," + exactNumber(c.position.z) + "," +
           exactNumber(c.yawDegrees, true) + "," + exactNumber(c.pitchDegrees, true);
}

const char* mirroredPlantCullName(MirroredPlantCull mode) {
    for (const MirroredPlantCullMode& row : kMirroredPlantCullModes)
        if (row.mode == mode) return row.name;
    return "auto";
}

// On/off for --help's synopsis: "on|off", "trimmed|whole".
std::string switchSynopsis(const OptionRow& row) { return std::string(row.on) + "|" + row.off; }

std::vector<OptionRow> makeRows() {
    std::vector<OptionRow> rows = {
        other("--size", "WxH", "frame size in pixels (default 1280x720)",
              [](const std::string& v, Options& o, Notes&, std::string& error) {
                  o.sizeGiven = true;
                  return parseSize(v, o.scene.width, o.scene.height, &error);
              },
              [](const SceneOptions& s) { return std::to_string(s.width) + "x" + std::to_string(s.height); }),
        other("--time", "SECONDS", "animation time: camera flight and time of day (default 0 = 10:00)",
              [](const std::string& v, Options& o, Notes&, std::string& error) {
                  return parseInDomain(v, inputDomain("--time"), o.scene.timeSeconds, error);
              },
              [](const SceneOptions& s) { return exactNumber(s.timeSeconds); }),
        other("--hour", "H", "override the hour of day (6 sunrise, 18 sunset)",
              [](const std::string& v, Options& o, Notes&, std::string& error) {
                  double hour = 0.0;
                  if (!parseInDomain(v, inputDomain("--hour"), hour, error)) return false;
                  o.scene.hour = hour;
                  return true;
              },
              [](const SceneOptions& s) { return s.hour ? exactNumber(*s.hour) : std::string(); }),
        other("--camera", "X,Y,Z,YAW,PITCH", "fixed camera instead of the flight (degrees; yaw 0 = -Z, 90 = +X)",
              [](const std::string& v, Options& o, Notes& notes, std::string& error) {
                  CameraPose pose;
                  std::string note;
                  if (!parseCameraPose(v, pose, &error, &note)) return false;
                  if (!note.empty()) notes.push_back(note);
                  o.scene.camera = pose;
                  return true;
              },
              [](const SceneOptions& s) { return cameraText(s); }),
        withBench(withWidget(twoWay("--reflections", "on", "off",
                                    "the mirrored scene in the water (default on; off reflects the sky alone)",
                                    [](SceneOptions& s) -> bool& { return s.water.reflections; }),
                             checkbox("water", "reflections")),
                  {"reflections", "the mirrored scene in the water", {"off", "on"}, 1}),
        withBench(withWidget(twoWay("--reflection-bounds", "on", "off",
                          "the reflection's passes clip to the rectangle of visible water the\n"
                          "water mask records (default on; off: the whole screen, stencil-masked)",
                          [](SceneOptions& s) -> bool& { return s.water.reflectionBounds; }),
                   checkbox("water", "reflection bounded to the visible water")),
                  {"reflection-bounds", "the reflection's full-screen draws clipped to the visible water, or the whole screen",
                   {"on", "off"}, 0}),
        withBench(withWidget(withChoices(other("--reflection-plant-cull", "M",
                                     "auto (default), on or off: the reflection's plants whose mirror image\n"
                                     "can land only on dry land culled on the CPU (full reflection resolution;\n"
                                     "the same picture); auto: while the camera stands still",
                                     [](const std::string& v, Options& o, Notes&, std::string& error) {
                                         const MirroredPlantCullMode* mode = findMirroredPlantCull(v);
                                         if (!mode) {
                                             error = "--reflection-plant-cull expects auto, on or off, got '" + v + "'";
                                             return false;
                                         }
                                         o.scene.work.mirroredPlantCull = mode->mode;
                                         return true;
                                     },
                                     [](const SceneOptions& s) { return std::string(mirroredPlantCullName(s.work.mirroredPlantCull)); }),
                               [] {
                                   std::vector<std::string> names;
                                   for (const MirroredPlantCullMode& mode : kMirroredPlantCullModes) names.push_back(mode.name);
                                   return names;
                               }),
                   radios("frame work", "reflected plants culled on dry land:")),
                  {"reflection-plant-cull", "the reflection's plants whose image lands only on dry land culled on the CPU "
                   "(auto: while the camera stands still, as it does over a configuration's timed frames)",
                   {"auto", "off"}, 0}),
        withBench(withWidget(withChoices(other("--reflection-resolution", "R",
                                     "full (default), half or quarter: the mirrored scene drawn at that\n"
                                     "fraction of the frame's width and height, upsampled bilinearly at the water",
                                     [](const std::string& v, Options& o, Notes&, std::string& error) {
                                         const ReflectionResolution* resolution = findReflectionResolution(v);
                                         if (!resolution) {
                                             error = "--reflection-resolution expects one of " +
                                                     std::string(kReflectionResolutionNames) + ", got '" + v + "'";
                                             return false;
                                         }
                                         o.scene.water.reflectionDivisor = resolution->divisor;
                                         return true;
                                     },
                                     [](const SceneOptions& s) { return std::string(reflectionResolutionName(s.water.reflectionDivisor)); }),
                               [] {
                                   std::vector<std::string> names;
                                   for (const ReflectionResolution& r : kReflectionResolutions) names.push_back(r.name);
                                   return names;
                               }),
                   radios("water", "reflection resolution")),
                  {"reflection-resolution", "the mirrored scene drawn at this fraction of the frame's width and "
                   "height, upsampled bilinearly", {"quarter", "half", "full"}, 2}),
        withWidget(twoWay("--shadows", "on", "off",
                          "the sun's cascaded shadows on terrain and plants (default on; none\n"
                          "are drawn while the sun is below the horizon)",
                          [](SceneOptions& s) -> bool& { return s.shadows.enabled; }),
                   checkbox("shadows", "sun shadows")),
        withWidget(withChoices(other("--shadow-quality", "Q",
                                     "low (default), medium or high: the cascade count and map size of one\n"
                                     "table (docs/shadows.md; the bench times each)",
                                     [](const std::string& v, Options& o, Notes&, std::string& error) {
                                         if (!findShadowQuality(v)) {
                                             error = "--shadow-quality expects one of " + shadowQualityNames() +
                                                     ", got '" + v + "'";
                                             return false;
                                         }
                                         o.scene.shadows.quality = v;
                                         return true;
                                     },
                                     [](const SceneOptions& s) { return s.shadows.quality; }),
                               [] {
                                   std::vector<std::string> names;
                                   for (const ShadowQuality& quality : shadowQualities()) names.push_back(quality.name);
                                   return names;
                               }),
                   radios("shadows", nullptr)),
        withWidget(number("--water-level", "Y", "world height of the water plane (default 0)",
                          [](SceneOptions& s) -> float& { return s.water.level; }),
                   slider("water", "level", -20.0f, 30.0f)),
        withWidget(number("--ripples", "S", "ripple strength, 0 = a still mirror (default 1)",
                          [](SceneOptions& s) -> float& { return s.water.rippleStrength; }),
                   slider("water", "ripples", 0.0f, 4.0f)),
        withWidget(number("--absorption", "A", "water absorption per unit depth, 0 = clear (default 0.09)",
                          [](SceneOptions& s) -> float& { return s.water.absorption; }),
                   slider("water", "absorption", 0.0f, 0.5f)),
        withWidget(twoWay("--vegetation", "on", "off", "the plant billboards (default on)",
                          [](SceneOptions& s) -> bool& { return s.vegetation.enabled; }),
                   checkbox("vegetation", "plants (V)")),
        withWidget(number("--vegetation-density", "D", "plants per unit of ground, times the default (default 1)",
                          [](SceneOptions& s) -> float& { return s.vegetation.density; }),
                   // Density re-places every chunk: applied when the slider is released, not per step.
                   slider("vegetation", "density", 0.0f, VegetationSettings::kMaxDensity, "%.2f", true)),
        withWidget(number("--wind", "S", "wind strength bending the plants (default 1)",
                          [](SceneOptions& s) -> float& { return s.vegetation.windStrength; }),
                   slider("vegetation", "wind", 0.0f, VegetationSettings::kMaxWindStrength)),
        withBench(withWidget(twoWay("--billboards", "trimmed", "whole",
                                    "plant billboards trimmed to their atlas cell's drawn bounds, or\n"
                                    "whole cells (default trimmed; whole: the reference for the trim)",
                                    [](SceneOptions& s) -> bool& { return s.vegetation.trimmedBillboards; }),
                             checkbox("vegetation", "billboards trimmed to the drawn plant")),
                  {"billboards", "plant billboards trimmed to their atlas cell's drawn bounds, or whole cells",
                   {"trimmed", "whole"}, 0}),
        withBench(withWidget(twoWay("--tone-map", "fused", "separate",
                                    "tone-map in the passes that write each pixel's colour last, or in a\n"
                                    "separate full-screen ToneMapPass (default fused; the same picture)",
                                    [](SceneOptions& s) -> bool& { return s.work.fuseToneMap; }),
                             checkbox("frame work", "tone map fused into the last colour passes")),
                  {"tone-map", "tone mapping fused into the passes that write each pixel last, or a separate pass",
                   {"fused", "separate"}, 0}),
        withBench(withWidget(twoWay("--depth-read", "in-place", "copy",
                                    "compact layout: the deferred lighting samples the depth-stencil target\n"
                                    "itself, or a copy made every frame (default in-place). Not bit for bit: the\n"
                                    "copy is written through gl_FragDepth, whose rounding to 24 bits moves some\n"
                                    "depths one step, so ~0.7% of pixels differ, nearly all by 1 level (a few by\n"
                                    "up to 8 where a shadow test flips)",
                                    [](SceneOptions& s) -> bool& { return s.work.depthReadInPlace; }),
                             checkbox("frame work", "compact: lighting reads depth in place")),
                  {"depth-read", "compact's lighting samples the depth-stencil target, or a copy made every frame",
                   {"in-place", "copy"}, 0}),
        other("--no-compute", "", "interpret the plant atlas on the CPU, not in a compute shader",
              [](const std::string&, Options& o, Notes&, std::string&) { return o.scene.noCompute = true; },
              [](const SceneOptions& s) { return std::string(s.noCompute ? "on" : "off"); }),
        other("--gl-debug", "",
              "synchronous GL debug output: stop at the first GL error, naming its\n"
              "debug group path; count performance warnings, printed at the end",
              [](const std::string&, Options& o, Notes&, std::string&) { return o.glDebug = true; }, nullptr),
        other("--lights", "N",
              "point lights (lanterns, fireflies) around the lake (default 0);\n"
              "they glow at night, e.g. --hour 21",
              [](const std::string& v, Options& o, Notes&, std::string& error) {
                  return parseIntInDomain(v, inputDomain("--lights"), o.scene.lights, error);
              },
              [](const SceneOptions& s) { return std::to_string(s.lights); }),
        other("--lights-path", "PATH",
              "how shaders read the lights: ssbo, ssbo-count or ubo (default: ssbo\n"
              "where the context has SSBOs, else ubo)",
              [](const std::string& v, Options& o, Notes&, std::string& error) {
                  LightsPath path;
                  if (!parseLightsPath(v, path)) {
                      error = "--lights-path expects one of " + lightsPathNames() + ", got '" + v + "'";
                      return false;
                  }
                  o.scene.lightsPath = path;
                  return true;
              },
              [](const SceneOptions& s) { return s.lightsPath ? std::string(lightsPathName(*s.lightsPath)) : std::string(); }),
        other("--light-method", "METHOD",
              "how the deferred pipeline adds the lights: volumes (stencil volumes,\n"
              "the default) or tiled (per-tile light lists from a compute pass; needs\n"
              "compute shaders and SSBOs, else volumes, saying why)",
              [](const std::string& v, Options& o, Notes&, std::string& error) {
                  LightMethod method;
                  if (!parseLightMethod(v, method)) {
                      error = "--light-method expects one of " + lightMethodNames() + ", got '" + v + "'";
                      return false;
                  }
                  o.scene.lightMethod = method;
                  return true;
              },
              [](const SceneOptions& s) { return s.lightMethod ? std::string(lightMethodName(*s.lightMethod)) : std::string(); }),
        other("--force", "LIST",
              "switch capabilities off even where the driver has them, to reproduce\n"
              "another driver: no-ssbo,no-compute,no-stencil-texturing,no-dsa,\n"
              "no-clip-control,gl33,gles30,no-depth-clamp,no-read-only-depth (gl33: an\n"
              "OpenGL 3.3 core context; gles30: the OpenGL ES context as ES 3.0, with\n"
              "--api gles; no-clip-control: reversed-z depth falls back to standard;\n"
              "no-depth-clamp: shadow casters flattened in the shader, as on ES 3.0;\n"
              "no-read-only-depth: compact's in-place lighting shades every pixel, not\n"
              "only the surfaces, as before GL 4.5);\n"
              "each fallback is reported once",
              [](const std::string& v, Options& o, Notes&, std::string& error) {
                  if (parseForcedFallbacks(v, o.scene.force, error)) return true;
                  error = "--force: " + error;
                  return false;
              },
              [](const SceneOptions& s) { return s.force.list(); }),
        other("--workarounds", "LIST",
              "the driver workarounds (docs/drivers.md): default (the table's, by\n"
              "GL_RENDERER and GL_VERSION), none, all, or a comma-separated list of\n",
              [](const std::string& v, Options& o, Notes&, std::string& error) {
                  return gl::parseWorkaroundsValue(v, o.scene.workarounds, error);
              },
              [](const SceneOptions& s) { return s.workarounds.value(); }),
        other("--workarounds-file", "FILE",
              "workarounds keyed by driver, one line each: NAME | RENDERER REGEX |\n"
              "VERSION REGEX (-NAME: off); applied before --workarounds (default:\n"
              "$OASIS_WORKAROUNDS)",
              [](const std::string& v, Options& o, Notes&, std::string& error) {
                  if (gl::readWorkaroundsFile(v, o.scene.workarounds, error)) return true;
                  error = "--workarounds-file: " + error;
                  return false;
              },
              [](const SceneOptions& s) { return s.workarounds.file; }),
        other("--api", "API",
              "gl (desktop OpenGL core, the default) or gles (an OpenGL ES 3.x context:\n"
              "ES 3.2 on Mesa; every command, the window included)",
              [](const std::string& v, Options& o, Notes&, std::string& error) {
                  if (gl::parseApi(v, o.scene.api)) return true;
                  error = "--api expects gl or gles, got '" + v + "'";
                  return false;
              },
              [](const SceneOptions& s) { return std::string(gl::apiName(s.api)); }),
        other("--depth", "CONVENTION",
              "depth buffer: standard (24-bit, near 0 far 1) or reversed-z (32-bit float,\n"
              "near 1 far 0; needs GL 4.5 or GL_ARB_clip_control) (default standard;\n"
              "`oasis bench` times and compares both itself)",
              [](const std::string& v, Options& o, Notes&, std::string& error) {
                  if (!findDepthConvention(v)) {
                      error = "--depth: unknown convention '" + v + "' (one of: " + depthConventionNames() + ")";
                      return false;
                  }
                  o.scene.depth = v;
                  return true;
              },
              [](const SceneOptions& s) { return s.depth; }),
        other("--gbuffer", "LAYOUT", "G-buffer layout: ",
              [](const std::string& v, Options& o, Notes&, std::string& error) {
                  if (!findGBufferLayout(v)) {
                      error = "--gbuffer: unknown layout '" + v + "' (one of: " + gbufferLayoutNames() + ")";
                      return false;
                  }
                  o.scene.gbuffer = v;
                  return true;
              },
              [](const SceneOptions& s) { return s.gbuffer; }),
    };
    for (OptionRow& row : rows) {
        if (row.flag == std::string("--gbuffer"))
            row.helpTail = [] { return gbufferLayoutNames() + " (default " + kDefaultGBufferLayoutName + ")"; };
        if (row.flag == std::string("--workarounds")) row.helpTail = [] { return gl::workaroundNames(); };
        if (row.flag == std::string("--no-compute") || row.flag == std::string("--gl-debug")) row.bare = true;
        // How this driver drew the picture, not what it shows; --gl-debug changes neither.
        for (const char* driver : {"--api", "--force", "--no-compute", "--lights-path", "--light-method", "--workarounds",
                                   "--workarounds-file"})
            if (row.flag == std::string(driver)) row.provenance = SceneArgumentKind::Driver;
        if (row.flag == std::string("--gl-debug")) row.provenance = SceneArgumentKind::None;
    }
    return rows;
}

}  // namespace

const std::vector<OptionRow>& optionTable() {
    static const std::vector<OptionRow> rows = makeRows();
    return rows;
}

const OptionRow* findOption(const std::string& flag) {
    for (const OptionRow& row : optionTable())
        if (flag == row.flag) return &row;
    return nullptr;
}

bool readOption(const OptionRow& row, const std::string& value, Options& options, std::vector<std::string>& notes,
                std::string& error) {
    if (row.isSwitch()) {
        if (value != row.on && value != row.off) {
            error = std::string(row.flag) + " expects " + row.on + " or " + row.off + ", got '" + value + "'";
            return false;
        }
        row.switchField(options.scene) = value == row.on;
        return true;
    }
    if (row.numberField) {
        double number = 0.0;
        if (!parseInDomain(value, inputDomain(row.flag), number, error)) return false;
        row.numberField(options.scene) = float(number);
        return true;
    }
    return row.read(value, options, notes, error);
}

std::string optionValue(const OptionRow& row, const SceneOptions& scene) {
    SceneOptions copy = scene;  // the fields are reached through mutable references
    if (row.isSwitch()) return row.switchField(copy) ? row.on : row.off;
    if (row.numberField) return exactNumber(row.numberField(copy), true);
    return row.write ? row.write(scene) : std::string();
}

std::string sceneOptionsHelp() {
    std::string help;
    for (const OptionRow& row : optionTable()) {
        std::string head = std::string(row.flag);
        std::string synopsis = row.isSwitch() ? switchSynopsis(row) : std::string(row.synopsis);
        if (!synopsis.empty()) head += " " + synopsis;
        // The descriptions start in column 28; a longer head keeps two spaces before its text.
        help += "  " + head + std::string(head.size() < 24 ? 26 - head.size() : 2, ' ');
        for (const char* c = row.help; *c; ++c) help += *c == '\n' ? "\n" + std::string(28, ' ') : std::string(1, *c);
        if (row.helpTail) help += row.helpTail();
        help += "\n";
    }
    return help;
}

// The pairs of fields the rows reach, a SceneOptions' and a SceneSettings', handed to `copy`.
template <class Options, class Settings, class Copy>
void forEachSceneField(Options& options, Settings& scene, Copy copy) {
    copy(options.timeSeconds, scene.timeSeconds);
    copy(options.hour, scene.hour);
    copy(options.camera, scene.camera);
    copy(options.water, scene.water);
    copy(options.shadows, scene.shadows);
    copy(options.vegetation, scene.vegetation);
    copy(options.work, scene.work);
    copy(options.lights, scene.lights.count);
    copy(options.lightsPath, scene.lights.path);
    copy(options.lightMethod, scene.lights.method);
}

SceneOptions sceneOptionsOf(const SceneSettings& scene) {
    SceneOptions options;
    forEachSceneField(options, scene, [](auto& to, const auto& from) { to = from; });
    return options;
}

void applySceneOptions(const SceneOptions& options, SceneSettings& scene) {
    forEachSceneField(options, scene, [](const auto& from, auto& to) { to = from; });
}

}  // namespace oasis
