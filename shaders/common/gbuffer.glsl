// The G-buffer's encoding, both ways: writeGBuffer stores a Surface (OUTPUT_GBUFFER variants),
// readGBuffer and the gbuffer* helpers get it back for the passes and views that read it. The
// layout's define picks the encoding (src/render/gbuffer_layout.cpp, the one table):
//   default          albedo rgb | normal xyz | position xyz, w 1 | info (power, intensity, flags)
//   GBUFFER_COMPACT  albedo rgb + intensity | octahedral normal rg (16-bit unorm) |
//                    no position: from the depth copy | info (power, flags)
#ifndef OASIS_GBUFFER_GLSL
#define OASIS_GBUFFER_GLSL
#include "common/frame_block.glsl"
#include "common/surface.glsl"
#include "common/depth.glsl"

// Unit vectors on an octahedron folded into [-1,1]^2, the pole along +y (most normals point up).
vec2 octahedralEncode(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    vec2 folded = n.xz;
    if (n.y < 0.0) folded = (1.0 - abs(n.zx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.z >= 0.0 ? 1.0 : -1.0);
    return folded;
}

vec3 octahedralDecode(vec2 e) {
    vec3 n = vec3(e.x, 1.0 - abs(e.x) - abs(e.y), e.y);
    float fold = max(-n.y, 0.0);
    n.x += n.x >= 0.0 ? -fold : fold;
    n.z += n.z >= 0.0 ? -fold : fold;
    return normalize(n);
}

#if defined(GBUFFER_COMPACT)
const int INFO_FLAGS_CHANNEL = OASIS_COMPACT_INFO_FLAGS_CHANNEL;
#else
const int INFO_FLAGS_CHANNEL = OASIS_INFO_FLAGS_CHANNEL;
#endif

// The info texel where nothing was drawn: the SKY flag (ClearPass writes the same from C++ in the
// layouts that keep Info's clear).
vec4 clearedInfo() {
    vec4 info = vec4(0.0);
    info[INFO_FLAGS_CHANNEL] = float(SURFACE_SKY) / 255.0;
    return info;
}

uint gbufferFlags(vec4 info) { return uint(round(info[INFO_FLAGS_CHANNEL] * 255.0)); }

#if defined(OUTPUT_GBUFFER)
layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec4 outNormal;
// Locations are the G-buffer framebuffer's slots: the stored targets in order, no gaps.
#if defined(GBUFFER_COMPACT)
layout(location = 2) out vec4 outInfo;
#else
layout(location = 2) out vec4 outPosition;
layout(location = 3) out vec4 outInfo;
#endif

void writeGBuffer(Surface s) {
#if defined(GBUFFER_COMPACT)
    outAlbedo = vec4(s.albedo, s.specularIntensity);
    outNormal = vec4(octahedralEncode(s.normal) * 0.5 + 0.5, 0.0, 0.0);
    outInfo = vec4(s.specularPower / 255.0, float(s.flags) / 255.0, 0.0, 0.0);
#else
    outAlbedo = vec4(s.albedo, 1.0);
    outNormal = vec4(s.normal, 0.0);
    outPosition = vec4(s.relativePosition, 1.0);  // w = 0 (the clear value) marks the sky
    outInfo = vec4(s.specularPower / 255.0, s.specularIntensity, float(s.flags) / 255.0, 1.0);
#endif
}

#else
uniform sampler2D gAlbedo;
uniform sampler2D gNormal;
uniform sampler2D gPosition;  // not bound in layouts that reconstruct position from depth
uniform sampler2D gInfo;
uniform sampler2D gDepth;     // the depth-stencil target in depth mode; read by those layouts only

uint gbufferFlagsAt(ivec2 pixel) { return gbufferFlags(texelFetch(gInfo, pixel, 0)); }

// Nothing drawn at the pixel (the sky). ClearPass clears no colour target of the compact layout:
// there its depth (read for the position anyway) still at the far plane says so, and the colour
// targets hold whatever an earlier frame left. The other layouts keep Info's clear to the SKY flag
// (no depth is bound to their readers).
bool gbufferSkyAt(ivec2 pixel) {
#if defined(GBUFFER_COMPACT)
    return depthAtFarPlane(texelFetch(gDepth, pixel, 0).r);
#else
    return (gbufferFlagsAt(pixel) & SURFACE_SKY) != 0u;
#endif
}

vec3 gbufferNormalAt(ivec2 pixel) {
#if defined(GBUFFER_COMPACT)
    return octahedralDecode(texelFetch(gNormal, pixel, 0).rg * 2.0 - 1.0);
#else
    return texelFetch(gNormal, pixel, 0).xyz;
#endif
}

// Camera-relative position (the mirror image where REFLECTED); undefined on sky pixels.
vec3 gbufferPositionAt(ivec2 pixel) {
#if defined(GBUFFER_COMPACT)
    vec2 screenUv = (vec2(pixel) + 0.5) / vec2(textureSize(gDepth, 0));
    return relativePositionFromDepth(screenUv, texelFetch(gDepth, pixel, 0).r);
#else
    return texelFetch(gPosition, pixel, 0).xyz;
#endif
}

Surface readGBuffer(ivec2 pixel) {
    vec4 albedo = texelFetch(gAlbedo, pixel, 0), info = texelFetch(gInfo, pixel, 0);
    Surface s;
    s.albedo = albedo.rgb;
    s.normal = gbufferNormalAt(pixel);
    s.relativePosition = gbufferPositionAt(pixel);
    s.specularPower = round(info.r * 255.0);
#if defined(GBUFFER_COMPACT)
    s.specularIntensity = albedo.a;
#else
    s.specularIntensity = info.g;
#endif
    s.flags = gbufferFlags(info);
    return s;
}

// The surface as the views and the probe show it: at a sky pixel the values the colour targets
// held when they were still cleared (0; the compact normal's (0, 0) texel decoded; SKY), never the
// undefined texels there; the position as the layout gives it (from depth: the far plane's point).
Surface gbufferSurfaceShownAt(ivec2 pixel) {
    Surface s = readGBuffer(pixel);
    if (!gbufferSkyAt(pixel)) return s;
    s.albedo = vec3(0.0);
    s.specularIntensity = 0.0;
    s.specularPower = 0.0;
    s.flags = SURFACE_SKY;
#if defined(GBUFFER_COMPACT)
    s.normal = octahedralDecode(vec2(-1.0));
#else
    s.normal = vec3(0.0);
    s.relativePosition = vec3(0.0);
#endif
    return s;
}

// A pixel of the G-buffer for a view drawn into a tile of any size (screenUv over the tile).
ivec2 gbufferPixelAt(vec2 screenUv) {
    ivec2 size = textureSize(gInfo, 0);
    return clamp(ivec2(screenUv * vec2(size)), ivec2(0), size - 1);
}
#endif

#endif
