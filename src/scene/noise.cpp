// CPU twin of shaders/common/noise.glsl. Keep the two in step: tests compare them.
#include "scene/noise.h"

#include <cmath>

namespace oasis {
namespace {

constexpr float kSkew = 0.36602540378f;
constexpr float kUnskew = 0.21132486540f;
constexpr float kScale = 99.204334582f;

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

glm::vec3 simplexNoise(glm::vec2 p) {
    glm::vec2 skewed = glm::floor(p + (p.x + p.y) * kSkew);
    glm::ivec2 cell = glm::ivec2(skewed);
    glm::vec2 x0 = p - skewed + (skewed.x + skewed.y) * kUnskew;
    glm::ivec2 step = x0.x > x0.y ? glm::ivec2(1, 0) : glm::ivec2(0, 1);
    glm::vec2 x1 = x0 - glm::vec2(step) + kUnskew;
    glm::vec2 x2 = x0 - 1.0f + 2.0f * kUnskew;
    glm::vec3 sum = simplexCorner(x0, cell) + simplexCorner(x1, cell + step) +
                    simplexCorner(x2, cell + glm::ivec2(1, 1));
    return kScale * sum;
}

glm::vec3 fractalNoise(glm::vec2 p, int octaves) {
    glm::vec3 result(0.0f);
    float amplitude = 1.0f;
    glm::vec2 jx(1.0f, 0.0f), jy(0.0f, 1.0f), q = p;
    for (int octave = 0; octave < octaves; ++octave) {
        glm::vec3 n = simplexNoise(q + glm::vec2(17.0f, -31.0f) * float(octave));
        glm::vec2 g(n.y, n.z);
        result.x += amplitude * n.x;
        result.y += amplitude * glm::dot(g, jx);
        result.z += amplitude * glm::dot(g, jy);
        q = glm::vec2(1.6f * q.x - 1.2f * q.y, 1.2f * q.x + 1.6f * q.y);
        jx = glm::vec2(1.6f * jx.x - 1.2f * jx.y, 1.2f * jx.x + 1.6f * jx.y);
        jy = glm::vec2(1.6f * jy.x - 1.2f * jy.y, 1.2f * jy.x + 1.6f * jy.y);
        amplitude *= 0.5f;
    }
    return result;
}

}  // namespace oasis
