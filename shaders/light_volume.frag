// Deferred point light, one per draw: shades the G-buffer surface under each pixel of the light's
// volume that the stencil marked, with the function the forward pipeline loops over; the result is
// added to Radiance (or Reflection). MARK_ONLY: the stencil-marking draw, no colour.
#include "common/frame_block.glsl"
#include "common/lights.glsl"

#if defined(MARK_ONLY)
void main() {}
#else
#include "common/gbuffer.glsl"
flat in vec4 vLightPositionRadius;   // the light, fetched by the vertex stage (light_volume.vert)
flat in vec4 vLightColourIntensity;
layout(location = 0) out vec4 outColour;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (gbufferSkyAt(pixel)) {
        outColour = vec4(0.0);
        return;
    }
    Surface s = readGBuffer(pixel);
    outColour = vec4(pointLightRadiance(s, PointLight(vLightPositionRadius, vLightColourIntensity)) * pointLightTransfer(s), 0.0);
}
#endif
