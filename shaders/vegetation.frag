// Plant billboard fragments: alpha-tested against the plant atlas, then emitted as a surface
// (G-buffer or shaded, by variant) with the same material maths in both pipelines.
#include "common/frame_block.glsl"
#include "common/surface.glsl"
#include "common/emit_surface.glsl"
#include "common/shared_constants.glsl"
#include "common/water_clip_fragment.glsl"

uniform sampler2D plantAtlas;  // premultiplied: a transparent black background, mipmapped

in vec2 vAtlasUv;
in vec3 vRelativePosition;
in vec3 vNormal;
in vec3 vTint;
in float vAtlasLod;  // the mip level from the billboard's projected size (vegetation.vert)

void main() {
#if defined(MIRRORED)
    const bool reflected = true;
#else
    const bool reflected = false;
#endif
    // The atlas's lines are a texel wide, so mip level L keeps about 2^-L of their coverage:
    // lowering the threshold with it keeps a far plant about a pixel thick instead of letting it
    // dissolve (the coverage preservation of alpha-tested mipmaps).
    float lod = max(vAtlasLod, 0.0);
    vec4 texel = textureLod(plantAtlas, vAtlasUv, lod);
    bool transparent = texel.a < max(0.5 * exp2(-lod), float(OASIS_PLANT_ALPHA_MIN)) || belowWater();
#if !defined(LIGHTS_UBO)
    if (transparent) discard;
#endif

    // The atlas colour is display-encoded; the plant's albedo is linear and at most 1.
    vec3 colour = texel.rgb / texel.a;
    Surface s;
    s.albedo = min(pow(colour, vec3(2.2)) * vTint * 0.4, vec3(1.0));
    s.normal = normalize(vNormal);
    s.relativePosition = vRelativePosition;
    s.specularPower = 8.0;
    s.specularIntensity = quantiseUnit(0.04);
    s.flags = SURFACE_PLANT | (reflected ? SURFACE_REFLECTED : 0u);
    emitSurface(s);
#if defined(LIGHTS_UBO)
    // Driver workaround: llvmpipe (Mesa 22.3) read wrong lights from the uniform block array,
    // indexed in the light loop, in fragments that ran on after a discard (found by the lights
    // tests: ubo differed from ssbo); taking every fragment through the loop first and discarding
    // afterwards keeps ubo = ssbo bit for bit. Costs the shading of the billboards' transparent
    // texels on this fallback path only.
    if (transparent) discard;
#endif
}
