// The check's dimensions and its covering set (check/check_cases.h).
#include "check/check_cases.h"

#include <algorithm>
#include <cstdio>
#include <set>
#include <tuple>

namespace oasis {
namespace {

// A value whose main path is the driver's own choice (no argument).
CheckValue path(const std::string& name, std::vector<std::string> arguments) {
    return {name, std::move(arguments), {}};
}
// A value that is part of what the frame shows: the main path keeps it.
CheckValue shown(const std::string& name, std::vector<std::string> arguments) {
    std::vector<std::string> main = arguments;
    return {name, std::move(arguments), std::move(main)};
}

// Every pose but the far lands (out of the lights' sight) has lights, so that every light path does
// visible work.
const std::vector<CheckDimension> kDimensions = {
    {"pose",
     {shown("day", {"--lights", "32"}),
      shown("low-sun", {"--hour", "8.5", "--camera", "420,14,170,60,-10", "--lights", "32"}),
      shown("dusk", {"--hour", "18.2", "--lights", "32"}),
      shown("night", {"--hour", "21.5", "--lights", "64"}),
      shown("water", {"--camera", "520,1.5,140,-90,-2", "--lights", "32"}),
      shown("far", {"--camera", "100000,90,100000,30,-8"})}},
    {"pipeline", {shown("deferred", {"--pipeline", "deferred"}), shown("forward", {"--pipeline", "forward"})}},
    {"gbuffer",
     {shown("compact", {"--gbuffer", "compact"}), shown("standard", {"--gbuffer", "standard"}),
      shown("full", {"--gbuffer", "full"})}},
    {"depth", {shown("standard-z", {"--depth", "standard"}), shown("reversed-z", {"--depth", "reversed-z"})}},
    {"shadows",
     {shown("shadows-low", {"--shadows", "on", "--shadow-quality", "low"}), shown("shadows-off", {"--shadows", "off"}),
      shown("shadows-medium", {"--shadows", "on", "--shadow-quality", "medium"}),
      shown("shadows-high", {"--shadows", "on", "--shadow-quality", "high"})}},
    {"reflections",
     {shown("reflection-full", {"--reflections", "on", "--reflection-resolution", "full"}),
      shown("reflections-off", {"--reflections", "off"}),
      shown("reflection-half", {"--reflections", "on", "--reflection-resolution", "half"}),
      shown("reflection-quarter", {"--reflections", "on", "--reflection-resolution", "quarter"})}},
    {"lights-path",
     {path("ssbo", {"--lights-path", "ssbo"}), path("ssbo-count", {"--lights-path", "ssbo-count"}),
      path("ubo", {"--lights-path", "ubo"})},
     true},
    {"light-method", {path("volumes", {"--light-method", "volumes"}), path("tiled", {"--light-method", "tiled"})}, true},
    {"plants", {path("plants-gpu", {}), path("plants-cpu", {"--no-compute"})}, true},
    // The stencil view's two paths draw the same image; the final frame shows neither.
    {"output",
     {shown("final", {"--view", "final"}), {"stencil-texturing", {"--view", "stencil", "--stencil-view", "texturing"},
                                            {"--view", "stencil"}},
      {"stencil-read-back", {"--view", "stencil", "--stencil-view", "read-back"}, {"--view", "stencil"}}}},
    {"tier",
     {path("native", {}), path("gl33", {"--force", "gl33"}), path("gles", {"--api", "gles"}),
      path("gles30", {"--api", "gles", "--force", "gles30"})},
     true},
};

int dimensionIndex(const std::string& name) {
    for (size_t d = 0; d < kDimensions.size(); ++d)
        if (kDimensions[d].name == name) return int(d);
    return -1;
}

bool is(int dimension, int value, const char* dimensionName, const char* valueName) {
    return kDimensions[size_t(dimension)].name == dimensionName &&
           kDimensions[size_t(dimension)].values[size_t(value)].name == valueName;
}

bool named(int e, int w, const char* dimension, std::initializer_list<const char*> names) {
    if (kDimensions[size_t(e)].name != dimension) return false;
    for (const char* name : names)
        if (kDimensions[size_t(e)].values[size_t(w)].name == name) return true;
    return false;
}

// One direction of a forbidden pair: value (d, v) rules out (e, w) (a tier that lacks a path).
bool forbids(int d, int v, int e, int w) {
    // OpenGL ES 3.0 has no storage buffers, compute shaders, stencil texturing or clip control.
    if (is(d, v, "tier", "gles30"))
        return named(e, w, "lights-path", {"ssbo", "ssbo-count"}) || named(e, w, "light-method", {"tiled"}) ||
               named(e, w, "plants", {"plants-gpu"}) || named(e, w, "output", {"stencil-texturing"}) ||
               named(e, w, "depth", {"reversed-z"});
    // Tiled lights read their tile lists from a storage buffer, beside the lights' own.
    if (is(d, v, "light-method", "tiled")) return named(e, w, "lights-path", {"ubo"});
    return false;
}

// Whether value (d, v) leaves dimension e idle: nothing e decides shows in the case's image, so a
// pair with e's value there proves nothing and is not counted as met.
bool idles(int d, int v, int e) {
    const std::string& other = kDimensions[size_t(e)].name;
    // The stencil view shows neither lights nor shadows.
    if (is(d, v, "output", "stencil-texturing") || is(d, v, "output", "stencil-read-back"))
        return other == "lights-path" || other == "light-method" || other == "shadows";
    // The forward pipeline's frame has no G-buffer layout and no light method.
    if (is(d, v, "pipeline", "forward")) return other == "gbuffer" || other == "light-method";
    // No shadow maps are drawn while the sun is below the horizon.
    if (is(d, v, "pose", "night")) return other == "shadows";
    // The lights stand around the lake, far out of sight of the far lands.
    if (is(d, v, "pose", "far")) return other == "lights-path" || other == "light-method";
    return false;
}

bool idleIn(const std::vector<int>& values, int dimension) {
    for (size_t d = 0; d < values.size(); ++d)
        if (values[d] >= 0 && int(d) != dimension && idles(int(d), values[d], dimension)) return true;
    return false;
}

using Pair = std::tuple<int, int, int, int>;  // dimension a < dimension b, their values

// The pairs a covering set must meet: compatible, and neither value idling the other's dimension.
std::set<Pair> requiredPairs() {
    std::set<Pair> pairs;
    for (size_t a = 0; a < kDimensions.size(); ++a)
        for (size_t b = a + 1; b < kDimensions.size(); ++b)
            for (size_t v = 0; v < kDimensions[a].values.size(); ++v)
                for (size_t w = 0; w < kDimensions[b].values.size(); ++w)
                    if (compatibleValues(int(a), int(v), int(b), int(w)) && !idles(int(a), int(v), int(b)) &&
                        !idles(int(b), int(w), int(a)))
                        pairs.insert({int(a), int(v), int(b), int(w)});
    return pairs;
}

// The pairs a complete case meets (no dimension of them idle there).
std::vector<Pair> pairsMet(const std::vector<int>& values) {
    std::vector<Pair> met;
    for (size_t d = 0; d < values.size(); ++d)
        for (size_t e = d + 1; e < values.size(); ++e)
            if (!idleIn(values, int(d)) && !idleIn(values, int(e))) met.push_back({int(d), values[d], int(e), values[e]});
    return met;
}

bool fits(const std::vector<int>& values, int dimension, int value) {
    for (size_t d = 0; d < values.size(); ++d)
        if (values[d] >= 0 && int(d) != dimension && !compatibleValues(int(d), values[d], dimension, value)) return false;
    return true;
}

// What each of the case's values adds: `which` is CheckValue::arguments or mainArguments.
std::vector<std::string> caseArgumentsOf(const CheckCase& c, std::vector<std::string> CheckValue::*which) {
    std::vector<std::string> arguments;
    for (size_t d = 0; d < kDimensions.size(); ++d) {
        const std::vector<std::string>& added = kDimensions[d].values[size_t(c.values[d])].*which;
        arguments.insert(arguments.end(), added.begin(), added.end());
    }
    return arguments;
}

}  // namespace

const std::vector<CheckDimension>& checkDimensions() { return kDimensions; }

bool compatibleValues(int dimensionA, int valueA, int dimensionB, int valueB) {
    return !forbids(dimensionA, valueA, dimensionB, valueB) && !forbids(dimensionB, valueB, dimensionA, valueA);
}

std::string CheckCase::name() const {
    char number[8];
    std::snprintf(number, sizeof(number), "%02d", index);
    std::string text = number;
    for (size_t d = 0; d < kDimensions.size(); ++d) text += "-" + kDimensions[d].values[size_t(values[d])].name;
    return text;
}

std::vector<std::string> CheckCase::arguments() const { return caseArgumentsOf(*this, &CheckValue::arguments); }
std::vector<std::string> CheckCase::mainPathArguments() const { return caseArgumentsOf(*this, &CheckValue::mainArguments); }

const CheckValue& CheckCase::value(const std::string& dimension) const {
    int d = dimensionIndex(dimension);
    return kDimensions[size_t(d)].values[size_t(values[size_t(d)])];
}

std::vector<CheckCase> coveringCases() {
    std::set<Pair> uncovered = requiredPairs();
    // The dimensions whose values idle others are decided right after the seed, so that the gains
    // of the rest are counted on what will show.
    std::vector<int> order = {dimensionIndex("output"), dimensionIndex("pipeline"), dimensionIndex("pose")};
    for (size_t d = 0; d < kDimensions.size(); ++d)
        if (std::find(order.begin(), order.end(), int(d)) == order.end()) order.push_back(int(d));
    std::vector<CheckCase> cases;
    while (!uncovered.empty()) {
        // Seed with the first pair not yet met, then give every other dimension the value that meets
        // the most unmet pairs with the values already chosen (ties: the earlier value), never one
        // that idles a seed dimension.
        auto [a, v, b, w] = *uncovered.begin();
        std::vector<int> values(kDimensions.size(), -1);
        values[size_t(a)] = v;
        values[size_t(b)] = w;
        for (int d : order) {
            if (values[size_t(d)] >= 0) continue;
            int best = -1, bestGain = -1;
            for (size_t x = 0; x < kDimensions[size_t(d)].values.size(); ++x) {
                if (!fits(values, d, int(x)) || idles(d, int(x), a) || idles(d, int(x), b)) continue;
                std::vector<int> trial = values;
                trial[size_t(d)] = int(x);
                int gain = 0;
                for (size_t e = 0; e < kDimensions.size(); ++e) {
                    if (trial[e] < 0 || int(e) == d || idleIn(trial, int(e)) || idleIn(trial, d)) continue;
                    Pair pair = int(e) < d ? Pair{int(e), trial[e], d, int(x)} : Pair{d, int(x), int(e), trial[e]};
                    gain += int(uncovered.count(pair));
                }
                if (gain > bestGain) bestGain = gain, best = int(x);
            }
            values[size_t(d)] = best;
            if (best < 0) break;  // the seed pair leaves this dimension no value: it cannot be met
        }
        if (std::count(values.begin(), values.end(), -1)) {
            uncovered.erase(uncovered.begin());  // pairCoverage() then reports it unmet
            continue;
        }
        for (const Pair& pair : pairsMet(values)) uncovered.erase(pair);
        CheckCase next;
        next.values = values;
        next.index = int(cases.size()) + 1;
        cases.push_back(next);
    }
    return cases;
}

std::vector<CheckCase> quickCases(const std::vector<CheckCase>& all) {
    std::set<std::pair<int, int>> unmet;
    for (size_t d = 0; d < kDimensions.size(); ++d)
        for (size_t v = 0; v < kDimensions[d].values.size(); ++v) unmet.insert({int(d), int(v)});
    std::vector<CheckCase> quick;
    while (!unmet.empty()) {
        const CheckCase* best = nullptr;
        int bestGain = 0;
        for (const CheckCase& c : all) {
            int gain = 0;
            for (size_t d = 0; d < c.values.size(); ++d) gain += int(unmet.count({int(d), c.values[d]}));
            if (gain > bestGain) bestGain = gain, best = &c;
        }
        if (!best) break;
        for (size_t d = 0; d < best->values.size(); ++d) unmet.erase({int(d), best->values[d]});
        quick.push_back(*best);
    }
    std::sort(quick.begin(), quick.end(), [](const CheckCase& x, const CheckCase& y) { return x.index < y.index; });
    return quick;
}

PairCoverage pairCoverage(const std::vector<CheckCase>& cases) {
    std::set<Pair> pairs = requiredPairs(), met;
    for (const CheckCase& c : cases)
        for (const Pair& pair : pairsMet(c.values))
            if (pairs.count(pair)) met.insert(pair);
    return {int(pairs.size()), int(met.size())};
}

}  // namespace oasis
