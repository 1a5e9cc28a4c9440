// The scene options written back as a command line, in the option rows' order (cli/option_table.h:
// each row's writer and provenance kind; tests/unit/scene_arguments_test.cpp: every row written
// is parsed back to the same options).
#include "cli/scene_arguments.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "cli/option_table.h"
#include "cli/options.h"

namespace oasis {

const std::vector<SceneArgument>& sceneArgumentTable() {
    static const std::vector<SceneArgument> table = [] {
        std::vector<SceneArgument> rows;
        for (const OptionRow& row : optionTable())
            if (row.provenance != SceneArgumentKind::None)
                rows.push_back({row.flag, row.provenance,
                                [](const SceneOptions& s, const char* flag) { return optionValue(*findOption(flag), s); },
                                row.bare});
        return rows;
    }();
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
