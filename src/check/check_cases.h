// `oasis check`'s cases: one table of dimensions (each path a driver may take or be forced to,
// and the poses that make each path do visible work), the pairs that cannot meet (a tier that
// rules a path out), and a covering set in which every compatible pair of values meets at least
// once, made by a deterministic greedy search so that every driver gets the same named cases.
#pragma once
#include <string>
#include <vector>

namespace oasis {

struct CheckValue {
    std::string name;                        // "ubo", "gles30", "night"
    std::vector<std::string> arguments;      // what it adds to `oasis render`
    std::vector<std::string> mainArguments;  // what the case's main path adds instead (a path's:
                                             // nothing, the driver's own choice)
};

struct CheckDimension {
    std::string name;  // "lights-path"
    std::vector<CheckValue> values;
    // Whether the value changes how the frame is computed, not what it shows (the main path then
    // leaves it to the driver).
    bool pathOnly = false;
};

const std::vector<CheckDimension>& checkDimensions();

// One case: a value index per dimension (checkDimensions() order).
struct CheckCase {
    std::vector<int> values;
    std::string name() const;                       // "07-night-deferred-compact-ubo-..."
    std::vector<std::string> arguments() const;     // `oasis render` arguments reproducing it
    const CheckValue& value(const std::string& dimension) const;
    // The same picture by the driver's own choice of every path (its main path): what the case is
    // compared with on the same driver.
    std::vector<std::string> mainPathArguments() const;
    int index = 0;  // 1-based, in the covering set's order
};

// Whether two values may meet in one case (a tier forbids some paths: ES 3.0 has no storage
// buffers, compute or stencil texturing; the forward pipeline has no G-buffer layout or light method).
bool compatibleValues(int dimensionA, int valueA, int dimensionB, int valueB);

// Every compatible pair of values covered at least once; deterministic.
std::vector<CheckCase> coveringCases();
// The --quick subset (cases of the covering set, so their names and references are shared): every
// value at least once.
std::vector<CheckCase> quickCases(const std::vector<CheckCase>& all);

// How many compatible pairs there are, and how many `cases` cover (the check prints both).
struct PairCoverage { int pairs = 0, covered = 0; };
PairCoverage pairCoverage(const std::vector<CheckCase>& cases);

}  // namespace oasis
