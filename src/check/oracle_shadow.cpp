// The CPU twin of sunShadow() (check/oracle_shadow.h).
#include "check/oracle_shadow.h"

#include "check/oracle_shading.h"

#include <algorithm>
#include <cmath>

namespace oasis {

const char* const kShadowPenumbra = "shadow penumbra";
const char* const kShadowDepthTie = "shadow depth tie";
const char* const kShadowCascadeEdge = "shadow cascade edge";

namespace {

// How far apart the CPU's double and the driver's float may put a receiver's depth (0..1 over the
// cascade's depth range, a few float roundings of values near 1) and its clip coordinates: within
// this of a texel's depth or of a cascade's bound the driver's answer could go either way.
constexpr double kDepthTie = 1.0 / 65536.0;
constexpr double kClipEdge = 1.0 / 16384.0;
// How far the tap positions' texel may move between the two evaluations (texels).
constexpr double kTexelSlack = 1.0 / 1024.0;

bool near(double value, double bound, double tolerance) { return std::fabs(value - bound) < tolerance; }

// tentFilteredShadow(): four 2x2 comparison taps spanning texels base - 1 .. base + 2 on each
// axis. Where every texel they read compares alike the weighted sum is exactly 0 or 9 (over 9),
// whatever weights the driver's filter gives; otherwise the visibility depends on the driver's
// filtering precision, which the GL leaves to it.
OracleSunShadow tentFiltered(const ShadowMapDepths& maps, glm::dvec3 coord, int cascade) {
    OracleSunShadow result;
    result.cascade = cascade;
    glm::dvec2 texel = glm::dvec2(coord.x, coord.y) * double(maps.size) - 0.5;
    int s0 = int(std::floor(texel.x - kTexelSlack)) - 1, s1 = int(std::floor(texel.x + kTexelSlack)) + 2;
    int t0 = int(std::floor(texel.y - kTexelSlack)) - 1, t1 = int(std::floor(texel.y + kTexelSlack)) + 2;
    int lit = 0, shadowed = 0;
    for (int t = t0; t <= t1; ++t)
        for (int s = s0; s <= s1; ++s) {
            // Clamped to the edge, as the map's sampler is (the cascade's margin keeps taps inside).
            double stored = maps.at(cascade, std::clamp(s, 0, maps.size - 1), std::clamp(t, 0, maps.size - 1));
            if (near(coord.z, stored, kDepthTie)) {
                result.leftOut = kShadowDepthTie;
                return result;
            }
            (coord.z <= stored ? lit : shadowed) += 1;  // GL_LEQUAL: the reference passes when nearer
        }
    if (lit && shadowed) result.leftOut = kShadowPenumbra;
    result.lit = lit ? 1.0 : 0.0;
    return result;
}

}  // namespace

OracleSunShadow oracleSunShadow(const FrameData& frame, const ShadowMapDepths& maps, glm::dvec3 position,
                                glm::dvec3 normal) {
    OracleSunShadow result;
    if (frame.shadow.x == 0.0f) return result;
    // Beyond the last cascade the shadows fade out: past the fade, nothing of the maps is seen.
    const double fade = smoothstepOf(frame.shadow.z, frame.shadow.w, glm::length(position));
    if (fade >= 1.0) return result;
    const int count = int(frame.shadow.y);
    const double mapSize = double(maps.size);
    const double margin = 2.0 * 2.0 / mapSize;
    for (int c = 0; c < count && c < maps.layers; ++c) {
        double texel = frame.shadowTexel[c], depthRange = frame.shadowDepthRange[c];
        glm::dvec3 p = position + normal * (texel * 1.5);  // SHADOW_NORMAL_OFFSET_TEXELS
        glm::dvec4 clip = glm::dmat4(frame.shadowMatrices[c]) * glm::dvec4(p, 1.0);
        double sphereFront = 1.0 - 2.0 * (texel * mapSize) / depthRange;
        bool onEdge = near(std::fabs(clip.x), 1.0 - margin, kClipEdge) || near(std::fabs(clip.y), 1.0 - margin, kClipEdge) ||
                      near(clip.z, 1.0, kClipEdge) || near(clip.z, sphereFront, kClipEdge);
        if (onEdge) {
            result.leftOut = kShadowCascadeEdge;
            return result;
        }
        if (std::fabs(clip.x) > 1.0 - margin || std::fabs(clip.y) > 1.0 - margin || clip.z >= 1.0 || clip.z <= sphereFront)
            continue;
        glm::dvec3 coord = glm::dvec3(clip) * 0.5 + 0.5;
        coord.z -= 1.0 * texel / depthRange;  // SHADOW_DEPTH_BIAS_TEXELS
        result = tentFiltered(maps, coord, c);
        if (!result.leftOut.empty()) return result;
        break;
    }
    result.lit = result.lit + (1.0 - result.lit) * fade;
    return result;
}

}  // namespace oasis
