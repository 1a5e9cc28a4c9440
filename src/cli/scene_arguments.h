// The scene options written back as a command line: one entry per option row (cli/option_table.h),
// saying how its value is written from SceneOptions and whether it sets what the picture shows or
// only how this driver draws it. A picture's options travel in its PNG this way (commands/provenance.h); parsing
// the arguments gives the same SceneOptions back.
#pragma once
#include <string>
#include <vector>

#include "cli/option_table.h"  // SceneArgumentKind: each row's

namespace oasis {

struct SceneOptions;

struct SceneArgument {
    const char* flag;
    SceneArgumentKind kind;
    // The value as it would be given ("" for an optional one that is not set); the option is
    // written only where this differs from a default SceneOptions'.
    std::string (*value)(const SceneOptions& scene, const char* flag);
    bool bare = false;  // a switch given without a value (--no-compute): "on" is written as the flag alone
};
const std::vector<SceneArgument>& sceneArgumentTable();
const SceneArgument* findSceneArgument(const std::string& flag);  // null for other flags

// The options of `kind` that differ from their defaults, in the table's order; Picture always
// starts with --size. E.g. {"--size", "160x90", "--hour", "18"}.
std::vector<std::string> sceneArguments(const SceneOptions& scene, SceneArgumentKind kind);

// Arguments as one line, separated by single spaces (no scene option's value holds a space), and
// back. splitArguments splits at spaces and drops empty items.
std::string joinArguments(const std::vector<std::string>& arguments);
std::vector<std::string> splitArguments(const std::string& line);
// Arguments as a shell would take them back: each quoted ('...') where it holds anything but
// letters, digits and _./:=,+-@% ("oasis render --out 'my frame.png'").
std::string shellCommandLine(const std::vector<std::string>& arguments);

// The shortest decimal text that reads back (strtod) as exactly `value`, or, with `asFloat`, as
// exactly the float `value` holds (the options kept as float: --ripples 0.09 not 0.0900000036).
std::string exactNumber(double value, bool asFloat = false);

}  // namespace oasis
