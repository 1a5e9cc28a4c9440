// CPU twin of shaders/common/sky.glsl (see sky_model.h). Keep it in step with the shader: the
// water and cloud tests check it against the direct sky pixels before they rely on it.
#include "sky_model.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "scene/noise.h"

namespace oasis::gputest {
namespace {

double smoothstep(double e0, double e1, double x) {
    double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}
float smoothstepF(float e0, float e1, float x) {
    float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// detailNoise() of common/detail_noise.glsl: the layer's origin and scale as the GPU reads them.
float detailNoise(const FrameData& f, int layer, glm::vec2 relativeXZ) {
    const glm::vec4 origin = f.detailNoiseOrigins[layer];
    const float scale = f.detailNoiseScales[layer / 4][layer % 4];
    // ivec2(origin.zw): whole cell numbers stored in float, exact.
    glm::ivec2 cell(int32_t(int64_t(origin.z)), int32_t(int64_t(origin.w)));
    return simplexNoiseSkewed(cell, glm::vec2(origin) + simplexSkew(relativeXZ * scale)).x;
}

}  // namespace

glm::dvec2 cloudCoverCpu(const FrameData& f, glm::dvec3 dd) {
    const glm::vec3 d(dd);
    const float above = float(OASIS_CLOUD_ALTITUDE) - f.cameraPosition.y;
    if (d.y <= 0.0f || above <= 0.0f) return glm::dvec2(0.0);
    const glm::vec2 onDeck = glm::vec2(d.x, d.z) * (above / d.y);
    const float n = 0.65f * detailNoise(f, OASIS_DETAIL_CLOUDS_BROAD, onDeck) +
                    0.35f * detailNoise(f, OASIS_DETAIL_CLOUDS_FINE, onDeck);
    const float fade = smoothstepF(0.03f, 0.18f, d.y) * smoothstepF(0.0f, 150.0f, above);
    return glm::dvec2(smoothstepF(0.05f, 0.5f, n) * fade, smoothstepF(0.3f, 0.85f, n));
}

// The star hash of a lattice cell: brightness 0..1, 0 for most cells.
static double starInCell(glm::ivec3 cell) {
    uint32_t h = uint32_t(cell.x) * 0x8da6b343u ^ uint32_t(cell.y) * 0xd8163841u ^ uint32_t(cell.z) * 0xcb1ab31fu;
    h ^= h >> 15u;
    h *= 0x2c1b3c6du;
    h ^= h >> 12u;
    return (h & 1023u) < 3u ? double((h >> 10u) & 255u) / 255.0 : 0.0;
}

double starCpu(const FrameData& f, glm::dvec3 d) {
    double night = 1.0 - smoothstep(-0.15, 0.02, double(f.sunDirection.y));
    if (night <= 0.0) return 0.0;
    glm::ivec3 cell(glm::floor(glm::vec3(d) * 300.0f));
    return 0.6 * starInCell(cell) * night * smoothstep(0.0, 0.15, d.y);
}

glm::dvec3 skyRadianceCpu(const FrameData& f, glm::dvec3 d) {
    const glm::dvec3 zenith(f.skyZenith), horizon(f.skyHorizon), sunRadiance(f.sunRadiance), sun(f.sunDirection);
    double up = std::clamp(d.y, 0.0, 1.0), down = std::clamp(-d.y, 0.0, 1.0);
    glm::dvec3 gradient = glm::mix(horizon, zenith, std::pow(up, 0.5)) * (1.0 - 0.35 * std::sqrt(down));
    double cosSun = glm::dot(d, sun), towards = std::max(cosSun, 0.0);
    glm::dvec3 glow = sunRadiance * (0.06 * std::pow(towards, 6.0) + 0.25 * std::pow(towards, 200.0));
    double disk = smoothstep(0.99990, 0.99994, cosSun) * (d.y < -0.02 ? 0.0 : 1.0);
    glm::dvec3 open = gradient + glow + sunRadiance * 8.0 * disk;
    // cloudRadiance(thickness), and the glow through the cloud's edges; stars only where it is clear.
    glm::dvec2 cloud = cloudCoverCpu(f, d);
    glm::dvec3 lit = sunRadiance * (0.22 + 0.18 * std::max(double(f.sunDirection.y), 0.0)) + 0.45 * (zenith + horizon);
    glm::dvec3 clouded = lit * glm::mix(1.0, 0.6, cloud.y) + 0.5 * glow;
    double clear = 1.0 - cloud.x;
    return glm::mix(open, clouded, 0.92 * cloud.x) + glm::dvec3(starCpu(f, d) * clear * clear);
}

bool skyIsSensitive(const FrameData& f, glm::dvec3 d) {
    if (glm::dot(d, glm::dvec3(f.sunDirection)) > 0.9998) return true;
    if (f.sunDirection.y >= 0.02f || d.y <= 0.0) return false;
    // At night: a star in the direction's lattice cell or in one the GPU's float ray may fall in
    // instead (the ray moved by 1e-5 per component, about 30 times its float rounding).
    for (int i = 0; i < 8; ++i) {
        glm::dvec3 moved = d + 1e-5 * glm::dvec3(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0);
        if (starInCell(glm::ivec3(glm::floor(glm::vec3(moved) * 300.0f))) > 0.0) return true;
    }
    return false;
}

}  // namespace oasis::gputest
