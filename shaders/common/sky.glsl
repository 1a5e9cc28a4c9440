// The procedural sky seen along a direction: a zenith-to-horizon gradient, the sun's glow and
// disk, and stars at night. The fog that hides the terrain's far edge uses the same colours.
#ifndef OASIS_SKY_GLSL
#define OASIS_SKY_GLSL

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

vec3 skyRadiance(vec3 direction) {
    float cosSun = dot(direction, frame.sunDirection.xyz);
    float disk = smoothstep(0.99990, 0.99994, cosSun) * step(-0.02, direction.y);
    return skyGradient(direction) + sunGlow(direction) + frame.sunRadiance.rgb * 8.0 * disk
         + stars(direction);
}

#endif
