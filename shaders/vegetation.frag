// Plant billboard fragments: alpha-tested against the plant atlas, then emitted as a surface
// (G-buffer or shaded, by variant) with the same material maths in both pipelines.
#include "common/frame_block.glsl"
#include "common/surface.glsl"
#include "common/emit_surface.glsl"

uniform sampler2D plantAtlas;  // premultiplied: a transparent black background, mipmapped

in vec2 vAtlasUv;
in vec3 vRelativePosition;
in vec3 vNormal;
in vec3 vTint;

void main() {
#if defined(MIRRORED)
    const bool reflected = true;
#else
    const bool reflected = false;
#endif
    // The mip level the sampler picks. The atlas's lines are a texel wide, so level L keeps about
    // 2^-L of their coverage: lowering the threshold with it keeps a far plant about a pixel thick
    // instead of letting it dissolve (the coverage preservation of alpha-tested mipmaps).
    vec2 texels = vAtlasUv * vec2(textureSize(plantAtlas, 0));
    float footprint = max(dot(dFdx(texels), dFdx(texels)), dot(dFdy(texels), dFdy(texels)));
    float lod = max(0.5 * log2(max(footprint, 1e-8)), 0.0);
    vec4 texel = texture(plantAtlas, vAtlasUv);
    if (texel.a < max(0.5 * exp2(-lod), 0.12)) discard;

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
}
