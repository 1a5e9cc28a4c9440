// Point lights for both pipelines: the light list behind one pair of accessors, lightCount() and
// lightAt(i), whose storage the variant's #define picks (every path reads the same bytes):
//   LIGHTS_SSBO        std430 storage block, runtime-sized array, count = lights.length()
//   LIGHTS_SSBO_COUNT  the same array, count read from a separate storage block (for drivers that
//                      fail to compile .length(), as AMD's did)
//   LIGHTS_UBO         std140 uniform blocks of LIGHTS_UBO_CAPACITY lights each (the capacity is
//                      derived at run time from GL_MAX_UNIFORM_BLOCK_SIZE and passed as a define),
//                      LIGHTS_UBO_BLOCKS of them as a block array so one loop sees every light in
//                      the same order as the other paths; the count from a small uniform block
//   (none)             no lights
// pointLightRadiance() is the one light's shading both pipelines use (the forward loop and the
// deferred light volumes), so forward and deferred agree.
#ifndef OASIS_LIGHTS_GLSL
#define OASIS_LIGHTS_GLSL
#include "common/light_data.glsl"
#include "common/storage_layout.glsl"
#include "common/surface.glsl"
#include "common/water.glsl"

#if defined(LIGHTS_SSBO) || defined(LIGHTS_SSBO_COUNT)
OASIS_STORAGE_LAYOUT(OASIS_BINDING_LIGHTS) readonly buffer LightBuffer {
    PointLight lights[];
};
PointLight lightAt(int i) { return lights[i]; }
#if defined(LIGHTS_SSBO)
int lightCount() { return lights.length(); }
#else
OASIS_STORAGE_LAYOUT(OASIS_BINDING_LIGHT_COUNT) readonly buffer LightCountBuffer {
    uvec4 lightCountValue;  // x = number of lights
};
int lightCount() { return int(lightCountValue.x); }
#endif

#elif defined(LIGHTS_UBO)
#ifndef LIGHTS_UBO_CAPACITY
#define LIGHTS_UBO_CAPACITY 2048  // 64 KiB of 32-byte lights (the run-time value replaces it)
#endif
#ifndef LIGHTS_UBO_BLOCKS
#define LIGHTS_UBO_BLOCKS 2
#endif
layout(std140) uniform LightBlock {
    PointLight lights[LIGHTS_UBO_CAPACITY];
} lightBlocks[LIGHTS_UBO_BLOCKS];
layout(std140) uniform LightCountBlock {
    uvec4 lightCountValue;  // x = number of lights (at most LIGHTS_UBO_CAPACITY * LIGHTS_UBO_BLOCKS)
};
int lightCount() { return int(lightCountValue.x); }
#if __VERSION__ >= 400
// i is dynamically uniform wherever this is called (a loop bound by the count, or a per-draw index).
PointLight lightAt(int i) { return lightBlocks[i / LIGHTS_UBO_CAPACITY].lights[i % LIGHTS_UBO_CAPACITY]; }
#else
// Before GLSL 4.00 a block array takes constant indices only: one branch per block (at most
// OASIS_LIGHTS_UBO_MAX_BLOCKS, which src/render/light_paths.cpp respects).
PointLight lightAt(int i) {
    int block = i / LIGHTS_UBO_CAPACITY, index = i % LIGHTS_UBO_CAPACITY;
#if LIGHTS_UBO_BLOCKS > 7
    if (block == 7) return lightBlocks[7].lights[index];
#endif
#if LIGHTS_UBO_BLOCKS > 6
    if (block == 6) return lightBlocks[6].lights[index];
#endif
#if LIGHTS_UBO_BLOCKS > 5
    if (block == 5) return lightBlocks[5].lights[index];
#endif
#if LIGHTS_UBO_BLOCKS > 4
    if (block == 4) return lightBlocks[4].lights[index];
#endif
#if LIGHTS_UBO_BLOCKS > 3
    if (block == 3) return lightBlocks[3].lights[index];
#endif
#if LIGHTS_UBO_BLOCKS > 2
    if (block == 2) return lightBlocks[2].lights[index];
#endif
#if LIGHTS_UBO_BLOCKS > 1
    if (block == 1) return lightBlocks[1].lights[index];
#endif
    return lightBlocks[0].lights[index];
}
#endif

#else
int lightCount() { return 0; }
PointLight lightAt(int i) { return PointLight(vec4(0.0), vec4(0.0)); }
#endif

// Whether a light's sphere reaches the surface (the light-volumes debug view counts these).
bool lightTouches(vec3 position, PointLight light) {
    return distance(light.positionRadius.xyz, position) < light.positionRadius.w;
}

// Inverse-square falloff, softened near the light (+1) and windowed so it is exactly zero at the
// radius: (1 - (d/r)^4)^2 / (d^2 + 1), as in Karis, "Real Shading in Unreal Engine 4" (2013).
float pointLightFalloff(float distanceToLight, float radius) {
    float ratio = distanceToLight / radius;
    float window = clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
    return window * window / (distanceToLight * distanceToLight + 1.0);
}

// One light's reflected radiance at the surface (Lambert + the sun's normalised Blinn-Phong),
// before what lies between the surface and the eye (pointLightTransfer).
vec3 pointLightRadiance(Surface s, PointLight light) {
    vec3 position = litPosition(s);
    vec3 toLight = light.positionRadius.xyz - position;
    float distanceToLight = length(toLight);
    if (distanceToLight >= light.positionRadius.w) return vec3(0.0);
    vec3 l = toLight / max(distanceToLight, 1e-4);
    vec3 n = normalize(s.normal);
    float diffuse = max(dot(n, l), 0.0);
    if (diffuse <= 0.0) return vec3(0.0);
    // Seen from the (mirrored, for a reflection) camera: the same eye ray as shadeSurface's.
    bool reflected = (s.flags & SURFACE_REFLECTED) != 0u;
    vec3 eyeToSurface = reflected ? vec3(s.relativePosition.x, -s.relativePosition.y, s.relativePosition.z)
                                  : s.relativePosition;
    vec3 halfway = normalize(l - normalize(eyeToSurface));
    float normalisation = (s.specularPower + 8.0) / 25.13274;  // (p + 8) / (8 pi)
    float specular = s.specularIntensity * normalisation * pow(max(dot(n, halfway), 0.0), s.specularPower);
    vec3 irradiance = light.colourIntensity.rgb * (light.colourIntensity.w *
                                                   pointLightFalloff(distanceToLight, light.positionRadius.w));
    return (s.albedo * diffuse + vec3(specular)) * irradiance;
}

// What reaches the eye of one unit of radiance leaving the surface: shadeSurface's water and fog
// are affine in the lit colour, so added light is scaled by their transmittance alone.
vec3 pointLightTransfer(Surface s) {
    bool reflected = (s.flags & SURFACE_REFLECTED) != 0u;
    vec3 transfer = vec3(1.0);
    if (!reflected) {
        vec3 eye = frame.cameraPosition.xyz;
        float under = underwaterLength(eye, eye + s.relativePosition);
        if (under > 0.0) transfer = exp(-frame.water.y * under * vec3(1.0, 0.45, 0.3));
    }
    vec3 eyeToSurface = reflected ? vec3(s.relativePosition.x, -s.relativePosition.y, s.relativePosition.z)
                                  : s.relativePosition;
    float fog = smoothstep(frame.terrainGridCounts.z, frame.terrainGridCounts.w, length(eyeToSurface));
    return transfer * (1.0 - fog);
}

// Every light at a surface, summed in list order (the forward pipeline's loop), then carried to the eye.
vec3 allPointLights(Surface s) {
    int count = lightCount();
    if (count == 0) return vec3(0.0);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < count; ++i) sum += pointLightRadiance(s, lightAt(i));
    return sum * pointLightTransfer(s);
}

#endif
