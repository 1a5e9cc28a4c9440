// Water: its level, how light is absorbed and scattered along the part of a ray under the plane,
// the rippled normal of its surface, and Schlick's Fresnel reflectance.
#ifndef OASIS_WATER_GLSL
#define OASIS_WATER_GLSL
#include "common/detail_noise.glsl"
#include "common/shared_constants.glsl"

float waterLevel() { return frame.water.x; }
bool reflectionsActive() { return (uint(frame.water.w) & OASIS_WATER_REFLECTIONS_FLAG) != 0u; }

// Length of the segment eye -> point (world space) that lies below the water plane.
float underwaterLength(vec3 eye, vec3 point) {
    float eyeHeight = eye.y - waterLevel(), pointHeight = point.y - waterLevel();
    if (eyeHeight >= 0.0 && pointHeight >= 0.0) return 0.0;
    float length = distance(eye, point);
    if (eyeHeight < 0.0 && pointHeight < 0.0) return length;
    float crossing = eyeHeight / (eyeHeight - pointHeight);  // fraction of the way from the eye
    return eyeHeight < 0.0 ? length * crossing : length * (1.0 - crossing);
}

// From an eye under water towards the sky: the way up to the surface (or all the way, looking down).
float underwaterLengthToSky(vec3 eye, vec3 direction) {
    float depth = waterLevel() - eye.y;
    if (depth <= 0.0) return 0.0;
    return direction.y > 1e-4 ? depth / direction.y : 1e6;
}

// The light deep water tends to: its tint lit by the sky and the sun.
vec3 waterScatter() {
    vec3 light = 0.5 * (frame.skyZenith.rgb + frame.skyHorizon.rgb) + 0.25 * frame.sunRadiance.rgb * max(frame.sunDirection.y, 0.0);
    return frame.waterTint.rgb * light;
}

// Radiance after `length` units of water: red is absorbed fastest, then green, then blue.
vec3 throughWater(vec3 radiance, float length) {
    if (length <= 0.0) return radiance;
    vec3 transmittance = exp(-frame.water.y * length * vec3(1.0, 0.45, 0.3));
    return radiance * transmittance + waterScatter() * (vec3(1.0) - transmittance);
}

// Surface normal with two layers of drifting ripples (detail noise around the camera), scaled by
// the ripple strength, at the point `relativeXZ` from the camera.
vec3 waterNormal(vec2 relativeXZ) {
    float strength = frame.water.z;
    if (strength == 0.0) return vec3(0.0, 1.0, 0.0);
    vec3 broad = detailNoise(OASIS_DETAIL_RIPPLE_BROAD, relativeXZ);
    vec3 fine = detailNoise(OASIS_DETAIL_RIPPLE_FINE, relativeXZ);
    vec2 slope = strength * (0.08 * detailNoiseScale(OASIS_DETAIL_RIPPLE_BROAD) * broad.yz +
                             0.025 * detailNoiseScale(OASIS_DETAIL_RIPPLE_FINE) * fine.yz);
    return normalize(vec3(-slope.x, 1.0, -slope.y));
}

float fresnelSchlick(float cosTheta) {
    float f0 = frame.waterTint.w;
    return f0 + (1.0 - f0) * pow(1.0 - clamp(cosTheta, 0.0, 1.0), 5.0);
}

#endif
