// Sun shadows on the CPU side: the one table of shadow qualities (cascade count and map size) and
// the fitting of each cascade to its slice of the view, in camera-relative coordinates built in
// double around the world position, so the maps are as stable 1e5 units out as at the origin.
#pragma once
#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/shared_constants.glsl"
#include "scene/camera.h"

namespace oasis {

struct ShadowQuality {
    const char* name;
    int cascades;  // 1..OASIS_SHADOW_MAX_CASCADES
    int mapSize;   // texels per side of each cascade's square depth map
};
const std::vector<ShadowQuality>& shadowQualities();
const ShadowQuality* findShadowQuality(const std::string& name);
const ShadowQuality& defaultShadowQuality();
std::string shadowQualityNames();  // "low, medium, high"

// The scene's shadow options (--shadows, --shadow-quality, the panel).
struct ShadowSettings {
    bool enabled = true;
    std::string quality = "low";  // a shadowQualities() name
};

struct ShadowCascades {
    int count = 0;  // 0: no maps this frame (shadows off, or the sun below the horizon)
    std::array<glm::mat4, OASIS_SHADOW_MAX_CASCADES> matrices{};  // camera-relative -> cascade clip
    glm::vec4 sliceEnd{0.0f};     // view depth where each cascade's slice ends
    glm::vec4 texel{0.0f};        // world units per texel
    glm::vec4 depthRange{0.0f};   // world units across each cascade's depth
    float fadeStart = 0.0f, fadeEnd = 0.0f;  // eye distances over which shadows fade out
    // Per cascade, the horizontal distances from the camera (x nearest, y farthest) between which
    // a caster within the casters' heights can shadow anything in the cascade's box: the box's
    // square swept towards the sun up to the highest caster (ShadowPass draws only those rings of
    // the terrain grid).
    std::array<glm::vec2, OASIS_SHADOW_MAX_CASCADES> casterReach{};
};

// How the casters nearer the sun than a cascade's sphere reach its map. Clamped: the box's depth
// spans the sphere and ShadowPass clamps nearer casters onto its front (GL_DEPTH_CLAMP). Contained:
// where there is no depth clamp (the ES 3.0 tier), the box reaches towards the sun up to the
// highest caster above its square, so no caster crosses its front. Flattening a vertex onto the
// front (common/shadow_caster.glsl) changes the depth slope of the triangles crossing it, so their
// slope-scaled polygon offset and depth move: shadows a few pixels apart from the clamped path's
// (check case 05: max abs 5 on SwiftShader, 8 on softpipe). Flattening remains the safety net
// past the reach's cap (a sun at the horizon).
enum class ShadowCasterDepth { Clamped, Contained };

// Fits `quality.cascades` cascades to the view out to `distance`: each slice's bounding sphere
// (its size depends only on the slice, so turning the camera does not resize the map) seen from
// the sun, its centre snapped to whole texels in world coordinates (so moving the camera moves
// no shadow edge by part of a texel). `toSun` unit; the caller decides whether the sun is up.
// `casterHeights`: the lowest and highest world height of any caster (the reach; the default
// reaches everywhere).
ShadowCascades fitShadowCascades(const CameraView& view, const glm::vec3& toSun, const ShadowQuality& quality,
                                 float distance, glm::vec2 casterHeights = glm::vec2(-1e6f, 1e6f),
                                 ShadowCasterDepth casterDepth = ShadowCasterDepth::Clamped);

}  // namespace oasis
