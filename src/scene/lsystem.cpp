// L-system rewriting and the preset table.
#include "scene/lsystem.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace oasis {
namespace {

// Replacement per byte value; nullptr means the symbol copies itself. A flat table keeps the
// inner loop free of map look-ups (the fractal plant's 8th generation has ~400k symbols).
using RuleTable = std::array<const std::string*, 256>;

RuleTable buildRuleTable(const LSystem& system) {
    RuleTable table{};
    for (const auto& [symbol, replacement] : system.rules)
        table[static_cast<unsigned char>(symbol)] = &replacement;
    return table;
}

uint64_t saturatingAdd(uint64_t a, uint64_t b) {
    uint64_t sum;
    return __builtin_add_overflow(a, b, &sum) ? UINT64_MAX : sum;
}

SymbolCounts rewriteCounts(const SymbolCounts& counts, const RuleTable& table) {
    SymbolCounts next{};
    for (std::size_t symbol = 0; symbol < counts.size(); ++symbol) {
        if (counts[symbol] == 0) continue;
        const std::string* replacement = table[symbol];
        if (!replacement) {
            next[symbol] = saturatingAdd(next[symbol], counts[symbol]);
            continue;
        }
        for (char produced : *replacement) {
            uint64_t& slot = next[static_cast<unsigned char>(produced)];
            slot = saturatingAdd(slot, counts[symbol]);
        }
    }
    return next;
}

std::string rewriteOnce(const std::string& generation, const RuleTable& table) {
    std::size_t length = 0;
    for (char symbol : generation) {
        const std::string* replacement = table[static_cast<unsigned char>(symbol)];
        length += replacement ? replacement->size() : 1;
    }
    std::string next;
    next.reserve(length);
    for (char symbol : generation) {
        const std::string* replacement = table[static_cast<unsigned char>(symbol)];
        if (replacement)
            next += *replacement;
        else
            next += symbol;
    }
    return next;
}

}  // namespace

std::string rewrite(const LSystem& system, int iterations, uint64_t maxLength) {
    uint64_t length = predictLength(system, iterations);
    if (length > maxLength)
        throw std::length_error("L-system rewrite would make " +
                                (length == UINT64_MAX ? std::string("over 2^64")
                                                      : std::to_string(length)) +
                                " symbols, more than " + std::to_string(maxLength));
    const RuleTable table = buildRuleTable(system);
    std::string generation = system.axiom;
    for (int i = 0; i < iterations; ++i) generation = rewriteOnce(generation, table);
    return generation;
}

std::string alphabet(const LSystem& system) {
    std::string symbols = system.axiom;
    for (const auto& [symbol, replacement] : system.rules) symbols += symbol + replacement;
    std::sort(symbols.begin(), symbols.end());
    symbols.erase(std::unique(symbols.begin(), symbols.end()), symbols.end());
    return symbols;
}

SymbolCounts countSymbols(std::string_view symbols) {
    SymbolCounts counts{};
    for (char symbol : symbols) ++counts[static_cast<unsigned char>(symbol)];
    return counts;
}

uint64_t countSymbol(std::string_view symbols, char symbol) {
    return static_cast<uint64_t>(std::count(symbols.begin(), symbols.end(), symbol));
}

SymbolCounts predictSymbolCounts(const LSystem& system, int iterations) {
    const RuleTable table = buildRuleTable(system);
    SymbolCounts counts = countSymbols(system.axiom);
    for (int i = 0; i < iterations; ++i) counts = rewriteCounts(counts, table);
    return counts;
}

uint64_t predictLength(const LSystem& system, int iterations) {
    uint64_t length = 0;
    for (uint64_t count : predictSymbolCounts(system, iterations))
        length = saturatingAdd(length, count);
    return length;
}

const std::vector<PlantPreset>& plantPresets() {
    // name, {axiom, rules, angle, default iterations}, segment length scale.
    // The scale is 1 / (number of F on the main axis of F's replacement): F -> FF halves,
    // F -> F[+F]F[-F]F (three F along the axis) thirds.
    static const std::vector<PlantPreset> presets = {
        // Wikipedia's fractal plant (a 25-degree variant of ABOP fig. 1.24f).
        {"fractal-plant", {"X", {{'X', "F+[[X]-X]-F[-FX]+X"}, {'F', "FF"}}, 25.0f, 6}, 0.5f},
        // ABOP fig. 1.24c: a dense bush, two side branches per segment.
        {"bush", {"F", {{'F', "FF-[-F+F+F]+[+F-F-F]"}}, 22.5f, 4}, 0.5f},
        // ABOP fig. 1.24a: a weed with alternating side shoots along a long axis.
        {"weed", {"F", {{'F', "F[+F]F[-F]F"}}, 25.7f, 5}, 1.0f / 3.0f},
        // ABOP fig. 1.24b: grass-like, a tuft of three shoots at each node.
        {"grass", {"F", {{'F', "F[+F]F[-F][F]"}}, 20.0f, 5}, 0.5f},
        // ABOP fig. 1.24e: binary branching at every node, a sprig of a young shrub.
        {"sprig", {"X", {{'X', "F[+X][-X]FX"}, {'F', "FF"}}, 25.7f, 7}, 0.5f},
    };
    return presets;
}

const PlantPreset* findPlantPreset(std::string_view name) {
    for (const PlantPreset& preset : plantPresets())
        if (preset.name == name) return &preset;
    return nullptr;
}

float segmentLength(const PlantPreset& preset, int iterations) {
    return std::pow(preset.segmentLengthScale, float(iterations));
}

}  // namespace oasis
