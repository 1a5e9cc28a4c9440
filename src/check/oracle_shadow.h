// The shading oracle's CPU twin of sunShadow() (shaders/common/shadows.glsl): the cascade that
// holds a point and the sun's visibility there, from the shadow maps' depths as the driver stored
// them. Only what the CPU can rebuild exactly is answered: where the 4x4 texels the tent filter
// reads all agree (visibility exactly 0 or 1 whatever the driver's filter weights); a penumbra
// (mixed texels), a depth within rounding of a texel's, or a point on a cascade's edge is named
// instead, and the oracle leaves that pixel out.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "render/frame_data.h"

namespace oasis {

// The shadow maps read back: `layers` square maps of `size` texels, layer after layer, rows
// bottom-up (t = 0 first), the depth each texel stores.
struct ShadowMapDepths {
    int size = 0, layers = 0;
    std::vector<float> depths;
    float at(int layer, int s, int t) const { return depths[(size_t(layer) * size_t(size) + size_t(t)) * size_t(size) + size_t(s)]; }
};

struct OracleSunShadow {
    double lit = 1.0;
    int cascade = -1;
    std::string leftOut;  // why the CPU cannot rebuild it ("shadow penumbra", ...), "" when it can
};

// sunShadow(position, normal) (camera-relative position, unit normal). `maps` may be empty when
// the frame drew no shadow maps (frame.shadow.x == 0).
OracleSunShadow oracleSunShadow(const FrameData& frame, const ShadowMapDepths& maps, glm::dvec3 position,
                                glm::dvec3 normal);

// The kinds of pixel oracleSunShadow leaves out, for the report.
extern const char* const kShadowPenumbra;
extern const char* const kShadowDepthTie;
extern const char* const kShadowCascadeEdge;

}  // namespace oasis
