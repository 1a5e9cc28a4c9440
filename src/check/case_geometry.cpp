// A check case's geometry from the oracle's inputs (check/case_geometry.h).
#include "check/case_geometry.h"

#include "common/shared_constants.glsl"

namespace oasis {
namespace {

// The sun's shadow at a surface as PixelSurface bits (the oracle's sunShadow twin); none where the
// frame draws no shadow, at water (its surface is not rebuilt) and at reflected surfaces.
uint8_t sunShadowOf(const OracleInputs& in, const OracleSurface& s, bool water) {
    if (in.frame.shadow.x == 0.0f || water || (s.flags & OASIS_SURFACE_REFLECTED)) return 0;
    glm::dvec3 n = glm::normalize(s.normal);
    if (!(glm::dot(n, glm::dvec3(in.frame.sunDirection)) > 0.0)) return 0;
    if (!in.shadowMapsUnreadable.empty()) return kPixelSunFacing | kPixelPenumbra;  // unknown: not held
    OracleSunShadow sun = oracleSunShadow(in.frame, in.shadowMaps, oracleLitPosition(in.frame, s), n);
    if (!sun.leftOut.empty()) return kPixelSunFacing | kPixelPenumbra;
    return kPixelSunFacing | (sun.lit < 0.5 ? kPixelShadowed : 0);
}

}  // namespace

PixelGeometry caseGeometry(const OracleInputs& in) {
    PixelGeometry g;
    g.width = in.width;
    g.height = in.height;
    const size_t count = size_t(in.width) * size_t(in.height);
    g.surface.assign(count, 0);
    g.distance.assign(count, 0.0f);
    g.normal.assign(3 * count, 0.0f);
    for (int y = 0; y < in.height; ++y)
        for (int x = 0; x < in.width; ++x) {
            const size_t at = size_t(in.height - 1 - y) * size_t(in.width) + size_t(x);  // GL rows are bottom-up
            uint8_t& surface = g.surface[at];
            if (oracleWaterAt(in, x, y)) surface |= kPixelWater;
            OracleSurface s;
            if (!oracleSurfaceAt(in, x, y, s)) {
                surface |= kPixelSky;
                continue;
            }
            if (s.flags & OASIS_SURFACE_PLANT) surface |= kPixelPlant;
            surface |= sunShadowOf(in, s, (surface & kPixelWater) != 0);
            g.distance[at] = float(glm::length(s.relativePosition));
            glm::dvec3 n = glm::length(s.normal) > 0.0 ? glm::normalize(s.normal) : glm::dvec3(0.0);
            for (int c = 0; c < 3; ++c) g.normal[3 * at + size_t(c)] = float(n[c]);
        }
    return g;
}

}  // namespace oasis
