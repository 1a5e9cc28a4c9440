// The scene options' table of text forms (cli/scene_arguments.h), in the order a picture's
// provenance lists them; each option's parsing is its row in cli/option_table.cpp
// (tests/unit/scene_arguments_test.cpp: every row written is parsed back to the same options).
#include "cli/scene_arguments.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "cli/option_table.h"
#include "cli/options.h"

namespace oasis {
namespace {

// A two-way switch's word, from its row (cli/option_table.h).
std::string switchValue(const SceneOptions& scene, const char* flag) { return optionValue(*findOption(flag), scene); }

std::string floatValue(float value) { return exactNumber(value, true); }

const char* mirroredPlantCullName(MirroredPlantCull mode) {
    for (const MirroredPlantCullMode& row : kMirroredPlantCullModes)
        if (row.mode == mode) return row.name;
    return "auto";
}

using Kind = SceneArgumentKind;

}  // namespace

const std::vector<SceneArgument>& sceneArgumentTable() {
    static const std::vector<SceneArgument> table = {
        {"--size", Kind::Picture,
         [](const SceneOptions& s, const char*) { return std::to_string(s.width) + "x" + std::to_string(s.height); }},
        {"--time", Kind::Picture, [](const SceneOptions& s, const char*) { return exactNumber(s.timeSeconds); }},
        {"--hour", Kind::Picture,
         [](const SceneOptions& s, const char*) { return s.hour ? exactNumber(*s.hour) : std::string(); }},
        {"--camera", Kind::Picture,
         [](const SceneOptions& s, const char*) {
             if (!s.camera) return std::string();
             const CameraPose& c = *s.camera;
             return exactNumber(c.position.x) + "," + exactNumber(c.position.y) + "," + exactNumber(c.position.z) +
                    "," + floatValue(c.yawDegrees) + "," + floatValue(c.pitchDegrees);
         }},
        {"--gbuffer", Kind::Picture, [](const SceneOptions& s, const char*) { return s.gbuffer; }},
        {"--depth", Kind::Picture, [](const SceneOptions& s, const char*) { return s.depth; }},
        {"--reflections", Kind::Picture, switchValue},
        {"--reflection-bounds", Kind::Picture, switchValue},
        {"--reflection-resolution", Kind::Picture,
         [](const SceneOptions& s, const char*) {
             return std::string(reflectionResolutionName(s.water.reflectionDivisor));
         }},
        {"--reflection-plant-cull", Kind::Picture,
         [](const SceneOptions& s, const char*) {
             return std::string(mirroredPlantCullName(s.work.mirroredPlantCull));
         }},
        {"--water-level", Kind::Picture, [](const SceneOptions& s, const char*) { return floatValue(s.water.level); }},
        {"--ripples", Kind::Picture,
         [](const SceneOptions& s, const char*) { return floatValue(s.water.rippleStrength); }},
        {"--absorption", Kind::Picture,
         [](const SceneOptions& s, const char*) { return floatValue(s.water.absorption); }},
        {"--vegetation", Kind::Picture, switchValue},
        {"--vegetation-density", Kind::Picture,
         [](const SceneOptions& s, const char*) { return floatValue(s.vegetation.density); }},
        {"--wind", Kind::Picture,
         [](const SceneOptions& s, const char*) { return floatValue(s.vegetation.windStrength); }},
        {"--billboards", Kind::Picture, switchValue},
        {"--tone-map", Kind::Picture, switchValue},
        {"--depth-read", Kind::Picture, switchValue},
        {"--shadows", Kind::Picture, switchValue},
        {"--shadow-quality", Kind::Picture, [](const SceneOptions& s, const char*) { return s.shadows.quality; }},
        {"--lights", Kind::Picture, [](const SceneOptions& s, const char*) { return std::to_string(s.lights); }},
        {"--api", Kind::Driver, [](const SceneOptions& s, const char*) { return std::string(gl::apiName(s.api)); }},
        {"--force", Kind::Driver, [](const SceneOptions& s, const char*) { return s.force.list(); }},
        {"--no-compute", Kind::Driver,
         [](const SceneOptions& s, const char*) { return std::string(s.noCompute ? "on" : "off"); }, true},
        {"--lights-path", Kind::Driver,
         [](const SceneOptions& s, const char*) {
             return s.lightsPath ? std::string(lightsPathName(*s.lightsPath)) : std::string();
         }},
        {"--light-method", Kind::Driver,
         [](const SceneOptions& s, const char*) {
             return s.lightMethod ? std::string(lightMethodName(*s.lightMethod)) : std::string();
         }},
    };
    return table;
}

const SceneArgument* findSceneArgument(const std::string& flag) {
    for (const SceneArgument& row : sceneArgumentTable())
        if (flag == row.flag) return &row;
    return nullptr;
}

std::vector<std::string> sceneArguments(const SceneOptions& scene, SceneArgumentKind kind) {
    static const SceneOptions kDefaults;
    std::vector<std::string> arguments;
    for (const SceneArgument& row : sceneArgumentTable()) {
        if (row.kind != kind) continue;
        std::string value = row.value(scene, row.flag);
        bool always = std::string(row.flag) == "--size";  // the frame's size is part of every picture
        if (!always && value == row.value(kDefaults, row.flag)) continue;
        arguments.push_back(row.flag);
        if (!row.bare) arguments.push_back(value);
    }
    return arguments;
}

std::string joinArguments(const std::vector<std::string>& arguments) {
    std::string line;
    for (const std::string& argument : arguments) line += (line.empty() ? "" : " ") + argument;
    return line;
}

std::vector<std::string> splitArguments(const std::string& line) {
    std::vector<std::string> arguments;
    size_t start = 0;
    for (size_t space; start <= line.size(); start = space + 1) {
        space = line.find(' ', start);
        if (space == std::string::npos) space = line.size();
        if (space > start) arguments.push_back(line.substr(start, space - start));
    }
    return arguments;
}

std::string shellCommandLine(const std::vector<std::string>& arguments) {
    std::string line;
    for (const std::string& argument : arguments) {
        bool plain = !argument.empty();
        for (char c : argument)
            plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || std::string("_./:=,+-@%").find(c) != std::string::npos);
        std::string quoted = "'";
        for (char c : argument) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
        line += (line.empty() ? "" : " ") + (plain ? argument : quoted + "'");
    }
    return line;
}

std::string exactNumber(double value, bool asFloat) {
    value += 0.0;  // -0 writes as 0
    auto exact = [&](const char* text) {
        double back = std::strtod(text, nullptr);
        return asFloat ? float(back) == float(value) : back == value;
    };
    // Plain decimals where a few suffice (420, not 4.2e+02), else the shortest exponent form.
    char text[400];
    for (int decimals = 0; decimals <= 17 && std::fabs(value) < 1e17; ++decimals) {
        std::snprintf(text, sizeof(text), "%.*f", decimals, value);
        if (exact(text)) return text;
    }
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(text, sizeof(text), "%.*g", digits, value);
        if (exact(text)) break;
    }
    return text;
}

}  // namespace oasis
