// Deferred lighting: reads one pixel's surface from the G-buffer and shades it with the same
// function the forward pipeline calls while drawing. The sky is SkyPass's, as in forward: the
// triangle lies at the far plane and is depth-tested to the surfaces where the context allows
// (LightingPass::testsSurfaces); where it is not, sky pixels (the SKY flag the clear leaves) are
// written black for SkyPass to draw over. MIRRORED: the same for the reflection, into Reflection.
// LIGHTS_TILED: also adds the point lights of the pixel's tile (the tiled light method; the list
// comes from light_tiles.comp), each with the light volumes' own pointLightRadiance().
// TONE_MAP_FUSED: also writes the display colour to Final (the separate ToneMapPass is skipped).
#include "common/frame_block.glsl"
#include "common/gbuffer.glsl"
#include "common/lighting.glsl"
#if defined(LIGHTS_TILED)
#include "common/lights.glsl"
#include "common/light_tiles.glsl"
#endif
#if defined(TONE_MAP_FUSED)
// Nothing adds to Radiance after this pass outside the water (no light volumes), so the display
// colour is written here and the water composite replaces it where water is seen.
#include "common/output.glsl"
layout(location = 1) out vec4 outFinal;
#endif

in vec2 vScreenUv;
layout(location = 0) out vec4 outColour;

#if defined(LIGHTS_TILED)
// The lights listed for the pixel's slice of its tile, or every light where that list overflowed
// (its count is past the maximum); either way in light order, then carried to the eye once, as the
// volumes do per light.
vec3 tiledPointLights(Surface s, ivec2 pixel) {
    int tileBase = lightTileOf(pixel, textureSize(gInfo, 0)) * LIGHT_TILE_STRIDE;
    float nearest = uintBitsToFloat(tileWords[tileBase]), farthest = uintBitsToFloat(tileWords[tileBase + 1]);
    int slice = lightSliceOf(lightSlicePosition(length(litPosition(s)), nearest, farthest));
    int base = tileBase + 2 + slice * LIGHT_SLICE_STRIDE;
    int count = int(tileWords[base]);
    if (count == 0) return vec3(0.0);
    vec3 sum = vec3(0.0);
    if (count <= LIGHT_TILE_MAX) {
        for (int k = 0; k < count; ++k) sum += pointLightRadiance(s, lightAt(int(tileWords[base + 1 + k])));
    } else {
        int everyLight = lightCount();
        for (int i = 0; i < everyLight; ++i) sum += pointLightRadiance(s, lightAt(i));
    }
    return sum * pointLightTransfer(s);
}
#endif

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (gbufferSkyAt(pixel)) {
        outColour = vec4(0.0, 0.0, 0.0, 1.0);
#if defined(TONE_MAP_FUSED)
        outFinal = vec4(0.0, 0.0, 0.0, 1.0);
#endif
        return;
    }
    Surface s = readGBuffer(pixel);
    vec3 radiance = shadeSurface(s);
#if defined(LIGHTS_TILED)
    radiance += tiledPointLights(s, pixel);
#endif
    outColour = vec4(radiance, 1.0);
#if defined(TONE_MAP_FUSED)
    outFinal = finalColour(radiance);
#endif
}
