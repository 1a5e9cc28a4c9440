// A shaded point as both pipelines see it: what the G-buffer stores (common/gbuffer.glsl) and
// what lighting reads. Specular power and intensity are quantised here, by the material, so an
// 8-bit target stores them exactly and forward and deferred shade with the same numbers.
#ifndef OASIS_SURFACE_GLSL
#define OASIS_SURFACE_GLSL

#include "common/frame_block.glsl"
#include "common/shared_constants.glsl"
const uint SURFACE_SKY = OASIS_SURFACE_SKY;              // nothing drawn: SkyPass draws the sky there
const uint SURFACE_REFLECTED = OASIS_SURFACE_REFLECTED;  // seen in the water: the mirrored scene
const uint SURFACE_PLANT = OASIS_SURFACE_PLANT;          // a plant billboard

struct Surface {
    vec3 albedo;            // linear reflectance
    vec3 normal;            // unit, world space, as the unmirrored surface faces
    vec3 relativePosition;  // where the camera sees it (the mirror image when REFLECTED) minus the camera
    float specularPower;    // integer 1..255
    float specularIntensity;// multiple of 1/255
    uint flags;
};

// Where a surface really is, camera-relative: a reflected surface's stored position is its
// mirror image across the water plane.
vec3 litPosition(Surface s) {
    vec3 p = s.relativePosition;
    if ((s.flags & SURFACE_REFLECTED) != 0u) p.y = 2.0 * (frame.water.x - frame.cameraPosition.y) - p.y;
    return p;
}

float quantiseUnit(float x) { return round(clamp(x, 0.0, 1.0) * 255.0) / 255.0; }

#endif
