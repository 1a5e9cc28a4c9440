// The table of every shader program oasis can request: a name, its stage files, its #defines.
// Passes ask the shader library for a program by name; the shader tests compile every entry.
// A program is either vertex + fragment, or (computeFile set, the others empty) one compute stage.
#pragma once
#include <string>
#include <vector>

namespace oasis {

struct ProgramVariant {
    std::string name;
    std::string vertexFile;
    std::string fragmentFile;
    std::vector<std::string> defines;  // each "NAME" or "NAME VALUE"
    std::string computeFile{};         // non-empty: a compute program (needs GL 4.3 or the ARB extensions)
    // The vertex stage's outputs a transform feedback captures, interleaved in this order (set
    // before linking; empty for programs that draw).
    std::vector<std::string> feedbackVaryings{};
    bool isCompute() const { return !computeFile.empty(); }
    // The files the program is built from: {compute} or {vertex, fragment}.
    std::vector<std::string> stageFiles() const {
        return isCompute() ? std::vector<std::string>{computeFile} : std::vector<std::string>{vertexFile, fragmentFile};
    }
};

// Every program: the fixed ones plus one per debug view (generated from the debug view table).
const std::vector<ProgramVariant>& programVariants();
const ProgramVariant* findProgramVariant(const std::string& name);

}  // namespace oasis
