// Debug views: one G-buffer, depth or stencil target remapped to a colour a person can read.
// The variant's VIEW_* define picks the remapping; debug/debug_views.cpp lists which view uses which.
// Each remapping also gives viewValue(), the quantity it shows as numbers (the columns of the view
// table's "values" text); the VIEW_VALUES variants write those into a float target, from which
// the view controls (channel, range, NaN/Inf/negative overlay) draw (shaders/view_mapping.frag).
#include "common/frame_block.glsl"
#include "common/gbuffer.glsl"

in vec2 vScreenUv;
layout(location = 0) out vec4 outColour;

// A perceptual ramp (dark blue - teal - yellow) for scalar fields.
vec3 ramp(float t) {
    t = clamp(t, 0.0, 1.0);
    vec3 low = vec3(0.05, 0.03, 0.25), mid = vec3(0.10, 0.60, 0.55), high = vec3(0.99, 0.91, 0.15);
    return t < 0.5 ? mix(low, mid, t * 2.0) : mix(mid, high, t * 2.0 - 1.0);
}

#if defined(VIEW_COLOUR)
uniform sampler2D sourceTexture;
vec3 viewColour() { return texture(sourceTexture, vScreenUv).rgb; }
vec4 viewValue() { return texture(sourceTexture, vScreenUv); }

#elif defined(VIEW_VEGETATION)
uniform sampler2D sourceTexture;
vec3 viewColour() {
    // Direct plant pixels only: in the deferred G-buffer the water holds the mirrored scene.
    uint flags = gbufferSurfaceShownAt(gbufferPixelAt(vScreenUv)).flags;
    bool plant = (flags & SURFACE_PLANT) != 0u && (flags & SURFACE_REFLECTED) == 0u;
    return plant ? texture(sourceTexture, vScreenUv).rgb : vec3(0.0);
}
vec4 viewValue() { return vec4(viewColour(), 1.0); }

#elif defined(VIEW_RADIANCE) || defined(VIEW_HDR)
#include "common/water.glsl"
uniform sampler2D sourceTexture;
// Reflection is not cleared: the mirrored passes write it at the water's pixels (stencil mark 2)
// only, so its views read it there and show 0 elsewhere and with reflections off (1 for them).
uniform int sourceWaterOnly;
uniform usampler2D gStencil;
vec4 sourceAt(vec2 uv) {
    if (sourceWaterOnly != 0 && (!reflectionsActive() || (texture(gStencil, uv).r & 0x7Fu) != 2u)) return vec4(0.0);
    return texture(sourceTexture, uv);
}
#if defined(VIEW_RADIANCE)
#include "common/output.glsl"
vec3 viewColour() { return displayEncode(sourceAt(vScreenUv).rgb); }
vec4 viewValue() { return sourceAt(vScreenUv); }  // linear, as stored
#else
// Linear light as stored, scaled by the view's exposure (2^stops) and gamma-encoded with no tone
// curve: what lies above 1 after the exposure clips to white, so the stops show the range.
uniform float viewExposure;
vec3 viewColour() { return pow(clamp(sourceAt(vScreenUv).rgb * viewExposure, 0.0, 1.0), vec3(1.0 / 2.2)); }
vec4 viewValue() { return sourceAt(vScreenUv); }
#endif

#elif defined(VIEW_ALBEDO)
vec3 viewColour() {
    // Linear reflectance, gamma-encoded so it reads like the frame; black where nothing was drawn.
    return pow(clamp(gbufferSurfaceShownAt(gbufferPixelAt(vScreenUv)).albedo, 0.0, 1.0), vec3(1.0 / 2.2));
}
vec4 viewValue() {  // linear albedo, specular intensity
    Surface s = gbufferSurfaceShownAt(gbufferPixelAt(vScreenUv));
    return vec4(s.albedo, s.specularIntensity);
}

#elif defined(VIEW_NORMAL)
vec3 viewColour() {
    ivec2 pixel = gbufferPixelAt(vScreenUv);
    if (gbufferSkyAt(pixel)) return vec3(0.5);  // the cleared normal, (0, 0, 0)
    return 0.5 + 0.5 * clamp(gbufferNormalAt(pixel), -1.0, 1.0);
}
vec4 viewValue() {
    vec3 n = gbufferSurfaceShownAt(gbufferPixelAt(vScreenUv)).normal;
    return vec4(n, length(n));
}

#elif defined(VIEW_POSITION)
vec3 viewColour() {
    // Camera-relative position on a signed log scale over the view distance: nearby detail and
    // the far hills both stay visible. Grey is the camera; red +x, green +y, blue +z. In layouts
    // without a position target this is the position reconstructed from depth.
    ivec2 pixel = gbufferPixelAt(vScreenUv);
    if (gbufferSkyAt(pixel)) return vec3(0.0);  // sky: no position
    vec3 p = gbufferPositionAt(pixel);
    vec3 scaled = sign(p) * log(1.0 + abs(p)) / log(1.0 + frame.terrainGridCounts.w);
    return 0.5 + 0.5 * clamp(scaled, -1.0, 1.0);
}
vec4 viewValue() {  // camera-relative xyz, distance; 0 on the sky
    ivec2 pixel = gbufferPixelAt(vScreenUv);
    if (gbufferSkyAt(pixel)) return vec4(0.0);
    vec3 p = gbufferPositionAt(pixel);
    return vec4(p, length(p));
}

#elif defined(VIEW_INFO)
vec3 viewColour() {
    // Red: specular power (0..64), green: specular intensity (0..0.25), blue: the flags, each its
    // own share (0.8 sky alone; otherwise 0.5 for REFLECTED plus 0.25 for PLANT).
    ivec2 pixel = gbufferPixelAt(vScreenUv);
    if (gbufferSkyAt(pixel)) return vec3(0.0, 0.0, 0.8);
    Surface s = readGBuffer(pixel);
    float flagMarks = ((s.flags & SURFACE_REFLECTED) != 0u ? 0.5 : 0.0) + ((s.flags & SURFACE_PLANT) != 0u ? 0.25 : 0.0);
    return vec3(s.specularPower / 64.0, s.specularIntensity / 0.25, flagMarks);
}
vec4 viewValue() {  // specular power, intensity, flags (the bits: SKY where nothing was drawn), 0
    Surface s = gbufferSurfaceShownAt(gbufferPixelAt(vScreenUv));
    return vec4(s.specularPower, s.specularIntensity, float(s.flags), 0.0);
}

#elif defined(VIEW_DEPTH)
vec3 viewColour() {
    // Window depth back to eye distance, then a log scale from the near to the far plane.
    float depth = texture(gDepth, vScreenUv).r;
    if (depthAtFarPlane(depth)) return vec3(0.0);
    float nearPlane = frame.depthRange.x, farPlane = frame.depthRange.y;
    return ramp(log(eyeDepthFromWindowDepth(depth) / nearPlane) / log(farPlane / nearPlane));
}
vec4 viewValue() {  // eye distance along the view axis (the far plane where cleared), window depth
    float depth = texture(gDepth, vScreenUv).r;
    return vec4(eyeDepthFromWindowDepth(depth), depth, 0.0, 0.0);
}

#elif defined(VIEW_STENCIL)
uniform usampler2D gStencil;
vec3 viewColour() {
    // Each stencil value its own colour: 0 black, 1 amber (terrain), then distinct hues.
    uint value = texture(gStencil, vScreenUv).r;
    if (value == 0u) return vec3(0.0);
    if (value == 1u) return vec3(0.95, 0.62, 0.12);  // terrain
    if (value == 2u) return vec3(0.15, 0.45, 0.95);  // water
    if (value == 3u) return vec3(0.20, 0.85, 0.35);  // plants
    float hue = fract(float(value) * 0.618034);
    return clamp(abs(mod(hue * 6.0 + vec3(0.0, 4.0, 2.0), 6.0) - 3.0) - 1.0, 0.0, 1.0);
}
vec4 viewValue() { return vec4(float(texture(gStencil, vScreenUv).r), 0.0, 0.0, 0.0); }

#elif defined(VIEW_LIGHT_VOLUMES)
// Light complexity: the lights whose sphere contains the G-buffer surface (where a reflection is
// stored, its real position), counted over the whole list read through the UBO path (the
// renderer binds every path's buffers each frame), as a heat map.
#define LIGHTS_UBO
#include "common/lights.glsl"
vec3 heat(float count) {
    const vec3 stops[6] = vec3[6](vec3(0.0, 0.0, 0.0), vec3(0.1, 0.2, 0.9), vec3(0.1, 0.8, 0.3),
                                  vec3(0.95, 0.9, 0.1), vec3(0.95, 0.15, 0.05), vec3(1.0, 1.0, 1.0));
    float t = clamp(log2(count) / 4.0, 0.0, 1.0) * 4.0 + 1.0;  // 1 -> blue, 2, 4, 8, 16+ -> white
    int i = min(int(floor(t)), 4);
    return mix(stops[i], stops[i + 1], t - float(i));
}
vec3 viewColour() {
    ivec2 pixel = gbufferPixelAt(vScreenUv);
    if (gbufferSkyAt(pixel)) return vec3(0.0);
    Surface s = readGBuffer(pixel);
    vec3 position = litPosition(s);
    int touching = 0;
    for (int i = 0; i < lightCount(); ++i)
        if (lightTouches(position, lightAt(i))) ++touching;
    // Surfaces no light reaches stay visible, dark grey shaded by their slope.
    if (touching == 0) return vec3(0.05 + 0.1 * clamp(s.normal.y, 0.0, 1.0));
    return heat(float(touching));
}
vec4 viewValue() {  // the lights reaching the surface, the lights in the list
    ivec2 pixel = gbufferPixelAt(vScreenUv);
    if (gbufferSkyAt(pixel)) return vec4(0.0, float(lightCount()), 0.0, 0.0);
    vec3 position = litPosition(readGBuffer(pixel));
    int touching = 0;
    for (int i = 0; i < lightCount(); ++i)
        if (lightTouches(position, lightAt(i))) ++touching;
    return vec4(float(touching), float(lightCount()), 0.0, 0.0);
}

#elif defined(VIEW_SHADOW)
// The sun's shadow as lighting reads it (common/shadows.glsl, at the surface's real position):
// which cascade answered and how lit the point is.
#include "common/shadows.glsl"
SunShadow shadowAt(ivec2 pixel, out float facing) {
    Surface s = readGBuffer(pixel);
    vec3 n = normalize(s.normal);
    facing = dot(n, frame.sunDirection.xyz);
    return sunShadow(litPosition(s), n);
}
vec3 viewColour() {
    ivec2 pixel = gbufferPixelAt(vScreenUv);
    if (gbufferSkyAt(pixel)) return vec3(0.0);
    float facing;
    SunShadow shadow = shadowAt(pixel, facing);
    const vec3 hues[4] = vec3[4](vec3(1.0, 0.3, 0.25), vec3(0.3, 1.0, 0.3), vec3(0.3, 0.45, 1.0), vec3(1.0, 0.9, 0.2));
    vec3 hue = shadow.cascade < 0 ? vec3(0.6) : hues[shadow.cascade];
    return hue * (0.15 + 0.85 * shadow.lit);
}
vec4 viewValue() {  // lit fraction, cascade (-1 none), n.l
    ivec2 pixel = gbufferPixelAt(vScreenUv);
    if (gbufferSkyAt(pixel)) return vec4(1.0, -1.0, 0.0, 0.0);
    float facing;
    SunShadow shadow = shadowAt(pixel, facing);
    return vec4(shadow.lit, float(shadow.cascade), facing, 0.0);
}

#else
#error "define one VIEW_* remapping"
#endif

void main() {
#if defined(VIEW_VALUES)
    outColour = viewValue();
#else
    outColour = vec4(viewColour(), 1.0);
#endif
}
