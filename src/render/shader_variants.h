// The table of every shader program oasis can request: a name, its stage files, its #defines.
// Passes ask the shader library for a program by name; the shader tests compile every entry.
// A program is either vertex + fragment, or (computeFile set, the others empty) one compute stage.
#pragma once
#include <deque>
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

// Every program: the fixed ones, then those a higher layer added (addProgramVariants), each with
// its G-buffer encoding variants. A deque, so a variant found stays where it is when more are added.
const std::deque<ProgramVariant>& programVariants();
const ProgramVariant* findProgramVariant(const std::string& name);

// A higher layer's programs, added to the table with their encoding variants: debug/ adds one pair
// per debug view (registerDebugViewPrograms in debug/debug_views.h), which the renderer calls, so
// this layer names nothing of debug/. Not thread-safe: add before other threads read the table.
void addProgramVariants(const std::vector<ProgramVariant>& variants);

}  // namespace oasis
