// The table of every shader program oasis can request: a name, its stage files, its #defines.
// Passes ask the shader library for a program by name; the shader tests compile every entry.
#pragma once
#include <string>
#include <vector>

namespace oasis {

struct ProgramVariant {
    std::string name;
    std::string vertexFile;
    std::string fragmentFile;
    std::vector<std::string> defines;  // each "NAME" or "NAME VALUE"
};

// Every program: the fixed ones plus one per debug view (generated from the debug view table).
const std::vector<ProgramVariant>& programVariants();
const ProgramVariant* findProgramVariant(const std::string& name);

}  // namespace oasis
