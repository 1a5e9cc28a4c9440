// CPU twin of shaders/common/noise.glsl. Keep the two in step: tests compare them.
#include "scene/noise.h"

#include <algorithm>
#include <cmath>

namespace oasis {
namespace {

constexpr float kSkew = 0.36602540378f;
constexpr float kUnskew = 0.21132486540f;
constexpr float kScale = 99.204334582f;

// Cell indices add modulo 2^32, as hashCell reads them: no signed overflow near the ends of int.
glm::ivec2 addCells(glm::ivec2 a, glm::ivec2 b) {
    return glm::ivec2(int32_t(uint32_t(a.x) + uint32_t(b.x)), int32_t(uint32_t(a.y) + uint32_t(b.y)));
}

// A whole float cell index to int. skewedOrigin keeps it within [-2^31, 2^31]; 2^31 itself (a
// rounded 2^31 - 1) goes through int64 and wraps to -2^31, the same cell for hashCell.
int cellIndex(float whole) { return int32_t(uint32_t(int64_t(whole))); }

glm::vec2 cellGradient(glm::ivec2 cell) {
    const float d = 0.70710678f;
    switch (hashCell(cell) & 7u) {
        case 0: return {1.0f, 0.0f};
        case 1: return {-1.0f, 0.0f};
        case 2: return {0.0f, 1.0f};
        case 3: return {0.0f, -1.0f};
        case 4: return {d, d};
        case 5: return {-d, d};
        case 6: return {d, -d};
        default: return {-d, -d};
    }
}

glm::vec3 simplexCorner(glm::vec2 x, glm::ivec2 cell) {
    float t = 0.5f - glm::dot(x, x);
    if (t <= 0.0f) return glm::vec3(0.0f);
    glm::vec2 g = cellGradient(cell);
    float gx = glm::dot(g, x);
    float t2 = t * t;
    float t4 = t2 * t2;
    glm::vec2 d = t4 * g - 8.0f * t2 * t * gx * x;
    return {t4 * gx, d.x, d.y};
}

}  // namespace

uint32_t hashCell(glm::ivec2 cell) {
    uint32_t h = uint32_t(cell.x) * 0x8da6b343u + uint32_t(cell.y) * 0xd8163841u;
    h ^= h >> 16u; h *= 0x7feb352du;
    h ^= h >> 15u; h *= 0x846ca68bu;
    h ^= h >> 16u;
    return h;
}

glm::vec2 simplexSkew(glm::vec2 p) { return p + (p.x + p.y) * kSkew; }

glm::vec3 simplexNoiseSkewed(glm::ivec2 baseCell, glm::vec2 skewedOffset) {
    glm::vec2 whole = glm::floor(skewedOffset);
    glm::ivec2 cell = addCells(baseCell, glm::ivec2(whole));
    glm::vec2 f = skewedOffset - whole;
    glm::vec2 x0 = f - (f.x + f.y) * kUnskew;
    glm::ivec2 step = x0.x > x0.y ? glm::ivec2(1, 0) : glm::ivec2(0, 1);
    glm::vec2 x1 = x0 - glm::vec2(step) + kUnskew;
    glm::vec2 x2 = x0 - 1.0f + 2.0f * kUnskew;
    glm::vec3 sum = simplexCorner(x0, cell) + simplexCorner(x1, addCells(cell, step)) +
                    simplexCorner(x2, addCells(cell, glm::ivec2(1, 1)));
    return kScale * sum;
}

glm::vec3 simplexNoise(glm::vec2 p) { return simplexNoiseSkewed(glm::ivec2(0), simplexSkew(p)); }

glm::vec4 skewedOrigin(glm::dvec2 p) {
    // The skew in double: F2 = (sqrt(3) - 1) / 2 to double precision.
    const double skew = 0.36602540378443865;
    glm::dvec2 skewed = p + (p.x + p.y) * skew;
    glm::dvec2 cell = glm::floor(skewed);
    glm::dvec2 fraction = skewed - cell;
    // The CLI's domains keep cells below 2^24, where floats hold them exactly. Any other finite
    // cell wraps modulo 2^32 (hashCell's period, so the noise is the same) into int's range, and a
    // non-finite point (NaN, or beyond double) reads as the origin: no cast below is undefined.
    if (!std::isfinite(cell.x) || !std::isfinite(cell.y) || !std::isfinite(fraction.x) || !std::isfinite(fraction.y))
        return glm::vec4(0.0f);
    const double period = 4294967296.0, half = 2147483648.0;
    auto wrap = [&](double index) {
        double wrapped = std::fmod(index + half, period);  // exact
        return (wrapped < 0.0 ? wrapped + period : wrapped) - half;
    };
    return {float(fraction.x), float(fraction.y), float(wrap(cell.x)), float(wrap(cell.y))};
}

namespace {
template <typename Vec2>
Vec2 nextOctave(Vec2 q) {
    return Vec2(1.6f * q.x - 1.2f * q.y, 1.2f * q.x + 1.6f * q.y);
}
glm::dvec2 nextOctaveExact(glm::dvec2 q) { return {1.6 * q.x - 1.2 * q.y, 1.2 * q.x + 1.6 * q.y}; }
int clampOctaves(int octaves) { return std::clamp(octaves, 0, kMaxNoiseOctaves); }
}  // namespace

NoiseOrigins fractalNoiseOrigins(glm::dvec2 p, int octaves) {
    NoiseOrigins origins{};
    glm::dvec2 q = p;
    for (int octave = 0; octave < clampOctaves(octaves); ++octave) {
        origins[size_t(octave)] = skewedOrigin(q + glm::dvec2(17.0, -31.0) * double(octave));
        q = nextOctaveExact(q);
    }
    return origins;
}

glm::vec3 fractalNoiseFrom(const NoiseOrigins& origins, glm::vec2 local, int octaves) {
    glm::vec3 result(0.0f);
    float amplitude = 1.0f;
    glm::vec2 jx(1.0f, 0.0f), jy(0.0f, 1.0f), q = local;
    for (int octave = 0; octave < clampOctaves(octaves); ++octave) {
        const glm::vec4& origin = origins[size_t(octave)];
        glm::vec3 n = simplexNoiseSkewed(glm::ivec2(cellIndex(origin.z), cellIndex(origin.w)),
                                         glm::vec2(origin) + simplexSkew(q));
        glm::vec2 g(n.y, n.z);
        result.x += amplitude * n.x;
        result.y += amplitude * glm::dot(g, jx);
        result.z += amplitude * glm::dot(g, jy);
        q = nextOctave(q);
        jx = nextOctave(jx);
        jy = nextOctave(jy);
        amplitude *= 0.5f;
    }
    return result;
}

glm::vec3 fractalNoise(glm::dvec2 p, int octaves) {
    return fractalNoiseFrom(fractalNoiseOrigins(p, octaves), glm::vec2(0.0f), octaves);
}

}  // namespace oasis
