// L-systems for the vegetation: rewriting rules applied on the CPU, symbol counting, and the one
// table of built-in plant presets (rules from Prusinkiewicz & Lindenmayer, "The Algorithmic Beauty
// of Plants", fig. 1.24, and Wikipedia's "fractal plant").
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace oasis {

// The alphabet is implied: every symbol in the axiom or a rule. A symbol without a rule copies
// itself on each rewrite (the usual OL-system convention), so constants such as + - [ ] need none.
struct LSystem {
    std::string axiom;
    std::map<char, std::string> rules;  // symbol -> replacement
    float angleDegrees = 0.0f;          // turtle turn for + and -
    int iterations = 0;                 // default number of rewrites
};

// Applies the rules `iterations` times in parallel (every symbol of one generation at once).
// Throws std::length_error, before building anything, if the result would exceed maxLength symbols.
constexpr uint64_t kMaxRewriteLength = uint64_t(1) << 28;
std::string rewrite(const LSystem& system, int iterations, uint64_t maxLength = kMaxRewriteLength);

// The distinct symbols of the axiom and the rules, sorted.
std::string alphabet(const LSystem& system);

// How often each byte value occurs; index with (unsigned char)symbol.
using SymbolCounts = std::array<uint64_t, 256>;
SymbolCounts countSymbols(std::string_view symbols);
uint64_t countSymbol(std::string_view symbols, char symbol);

// The counts rewrite() would produce, found without building the string (each symbol's count
// multiplies through its replacement's counts); saturates at UINT64_MAX. Sizes GPU buffers too.
SymbolCounts predictSymbolCounts(const LSystem& system, int iterations);
uint64_t predictLength(const LSystem& system, int iterations);

// A named plant: its L-system and how its segments shrink as iterations are added.
struct PlantPreset {
    std::string name;
    LSystem system;
    // Per-iteration shrink of one F, chosen so the plant's main axis keeps about the same length
    // whatever the iteration count (the axis grows by 1/scale per rewrite: F -> FF gives 0.5).
    float segmentLengthScale = 1.0f;
};

// The built-in presets, in a fixed order (variant indices refer to it).
const std::vector<PlantPreset>& plantPresets();
// nullptr when no preset has that name.
const PlantPreset* findPlantPreset(std::string_view name);
// Length of one F after `iterations` rewrites: segmentLengthScale^iterations.
float segmentLength(const PlantPreset& preset, int iterations);

}  // namespace oasis
