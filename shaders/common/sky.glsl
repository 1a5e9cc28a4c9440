// The procedural sky seen along a direction: a zenith-to-horizon gradient, the sun's glow and
// disk, clouds, and stars at night. The fog that hides the terrain's far edge uses the same
// colours (without the clouds, which lie far above the terrain's edge).
#ifndef OASIS_SKY_GLSL
#define OASIS_SKY_GLSL
#include "common/detail_noise.glsl"
#include "common/shared_constants.glsl"

vec3 skyGradient(vec3 direction) {
    float up = clamp(direction.y, 0.0, 1.0);
    vec3 gradient = mix(frame.skyHorizon.rgb, frame.skyZenith.rgb, pow(up, 0.5));
    // Below the horizon the haze darkens a little towards the ground.
    float down = clamp(-direction.y, 0.0, 1.0);
    return gradient * (1.0 - 0.35 * sqrt(down));
}

vec3 sunGlow(vec3 direction) {
    float towardsSun = max(dot(direction, frame.sunDirection.xyz), 0.0);
    return frame.sunRadiance.rgb * (0.06 * pow(towardsSun, 6.0) + 0.25 * pow(towardsSun, 200.0));
}

// The colour distant terrain fades into: the sky without its disk and stars.
vec3 fogColour(vec3 direction) {
    return skyGradient(vec3(direction.x, max(direction.y, 0.0), direction.z)) + sunGlow(direction);
}

vec3 stars(vec3 direction) {
    // Directions snapped to a fine lattice; a few cells in a thousand hold a star.
    ivec3 cell = ivec3(floor(direction * 300.0));
    uint h = uint(cell.x) * 0x8da6b343u ^ uint(cell.y) * 0xd8163841u ^ uint(cell.z) * 0xcb1ab31fu;
    h ^= h >> 15u; h *= 0x2c1b3c6du; h ^= h >> 12u;
    float brightness = (h & 1023u) < 3u ? float((h >> 10u) & 255u) / 255.0 : 0.0;
    float night = 1.0 - smoothstep(-0.15, 0.02, frame.sunDirection.y);
    return vec3(0.6) * brightness * night * smoothstep(0.0, 0.15, direction.y);
}

// The cloud deck along a direction: (cover 0..1, thickness 0..1). Two detail-noise layers on the
// deck, drifting with the wind; cover fades towards the horizon, where the deck's cells shrink to
// less than a pixel, and when the eye nears the deck (from above it there are none).
// The water's reflection asks for the mirrored ray from the same eye: strictly the deck should be
// seen from the mirrored eye, 2h lower for an eye h above the water, which moves a cell by 2h /
// (deck height above the water) of its distance (under 2% for h = 10). Kept so: the reflected sky
// stays exactly the sky along the mirrored ray (tests/gpu/water_test.cpp holds it to that), and the
// CPU twin of this function is tests/gpu/sky_model.cpp.
vec2 cloudCover(vec3 direction) {
    float above = float(OASIS_CLOUD_ALTITUDE) - frame.cameraPosition.y;
    if (direction.y <= 0.0 || above <= 0.0) return vec2(0.0);
    vec2 onDeck = direction.xz * (above / direction.y);  // relative to the camera
    float n = 0.65 * detailNoise(OASIS_DETAIL_CLOUDS_BROAD, onDeck).x + 0.35 * detailNoise(OASIS_DETAIL_CLOUDS_FINE, onDeck).x;
    float fade = smoothstep(0.03, 0.18, direction.y) * smoothstep(0.0, 150.0, above);
    return vec2(smoothstep(0.05, 0.5, n) * fade, smoothstep(0.3, 0.85, n));
}

// Clouds scatter the sun's light (its colour at dawn and dusk, none at night) and the sky's;
// thick cells are darker underneath.
vec3 cloudRadiance(float thickness) {
    vec3 lit = frame.sunRadiance.rgb * (0.22 + 0.18 * max(frame.sunDirection.y, 0.0)) +
               0.45 * (frame.skyZenith.rgb + frame.skyHorizon.rgb);
    return lit * mix(1.0, 0.6, thickness);
}

vec3 skyRadiance(vec3 direction) {
    float cosSun = dot(direction, frame.sunDirection.xyz);
    float disk = smoothstep(0.99990, 0.99994, cosSun) * step(-0.02, direction.y);
    vec2 cloud = cloudCover(direction);
    vec3 open = skyGradient(direction) + sunGlow(direction) + frame.sunRadiance.rgb * 8.0 * disk;
    // The sun's glow still shows through the cloud's edges, and its disk dimly through a thick cell;
    // stars are too faint for that: any cover hides them, a thin edge already most of their light.
    vec3 clouded = mix(open, cloudRadiance(cloud.y) + 0.5 * sunGlow(direction), 0.92 * cloud.x);
    float clear = 1.0 - cloud.x;
    return clouded + stars(direction) * (clear * clear);
}

#endif
