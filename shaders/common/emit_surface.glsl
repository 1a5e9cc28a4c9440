// Where a surface goes once the material has built it, chosen by the variant's #define:
// OUTPUT_GBUFFER stores it in the G-buffer in the layout's encoding; OUTPUT_FORWARD shades it now (linear),
// looping over the point lights of the variant's LIGHTS_* path; TONE_MAP_FUSED also writes Final;
// OUTPUT_SHADOW keeps only the depth (the sun's shadow casters).
#ifndef OASIS_EMIT_SURFACE_GLSL
#define OASIS_EMIT_SURFACE_GLSL
#include "common/surface.glsl"

#if defined(OUTPUT_GBUFFER)
#include "common/gbuffer.glsl"
void emitSurface(Surface s) { writeGBuffer(s); }
#elif defined(OUTPUT_FORWARD)
#include "common/lighting.glsl"
#include "common/lights.glsl"
layout(location = 0) out vec4 outColour;
#if defined(TONE_MAP_FUSED)
#include "common/output.glsl"
layout(location = 1) out vec4 outFinal;  // the display colour too: the last surface drawn here wins both
#endif
void emitSurface(Surface s) {
    // The sun and sky, then every point light (none unless the variant defines a LIGHTS_* path).
    vec3 radiance = shadeSurface(s) + allPointLights(s);
    outColour = vec4(radiance, 1.0);
#if defined(TONE_MAP_FUSED)
    outFinal = finalColour(radiance);
#endif
}
#elif defined(OUTPUT_SHADOW)
// A shadow caster writes depth only (passes/shadow_pass.h): nothing of the surface is kept.
void emitSurface(Surface s) {}
#else
#error "define OUTPUT_GBUFFER, OUTPUT_FORWARD or OUTPUT_SHADOW"
#endif

#endif
