// The pixel probe (`oasis probe`, the window's inspector): decodes one G-buffer pixel through the
// same common/gbuffer.glsl the lighting pass reads it with, and writes each quantity to one texel
// of a small float target (src/frame/pixel_probe.cpp reads them back by these slots).
#include "common/frame_block.glsl"
#include "common/gbuffer.glsl"
#define LIGHTS_UBO
#include "common/lights.glsl"
#include "common/shadows.glsl"

uniform ivec2 probePixel;              // GL's pixel coordinates, bottom row 0
uniform sampler2D probeDepthStencil;   // the depth-stencil target itself, in depth mode

layout(location = 0) out vec4 outValue;

void main() {
    int slot = int(gl_FragCoord.x);
    Surface s = gbufferSurfaceShownAt(probePixel);  // the cleared values at a sky pixel
    float depth = texelFetch(probeDepthStencil, probePixel, 0).r;
    bool sky = gbufferSkyAt(probePixel);
    if (slot == 0) outValue = vec4(s.albedo, s.specularIntensity);
    else if (slot == 1) outValue = vec4(s.normal, length(s.normal));
    else if (slot == 2) outValue = vec4(s.relativePosition, length(s.relativePosition));
    else if (slot == 3) outValue = vec4(s.specularPower, s.specularIntensity, float(s.flags), sky ? 1.0 : 0.0);
    else if (slot == 4) outValue = vec4(depth, eyeDepthFromWindowDepth(depth), depthAtFarPlane(depth) ? 1.0 : 0.0, 0.0);
    else if (slot == 5) {
        // The point lights whose sphere holds the surface (at its real position for a reflection),
        // as the light-volumes view counts them.
        int touching = 0;
        vec3 position = litPosition(s);
        if (!sky)
            for (int i = 0; i < lightCount(); ++i)
                if (lightTouches(position, lightAt(i))) ++touching;
        outValue = vec4(float(touching), float(lightCount()), litPosition(s).y, 0.0);
    }
    else if (slot == 7) {
        // The sun's shadow at the surface's real position, as shadeSurface reads it.
        vec3 n = normalize(s.normal);
        // No ?: over structs: WebGL (ANGLE) refuses it ("not allowed for structures").
        SunShadow shadow = SunShadow(1.0, -1);
        if (!sky) shadow = sunShadow(litPosition(s), n);
        outValue = vec4(shadow.lit, float(shadow.cascade), sky ? 0.0 : dot(n, frame.sunDirection.xyz), 0.0);
    }
#if defined(GBUFFER_COMPACT)
    // The depth the position was reconstructed from (the depth-stencil target's, as lighting reads it).
    else if (slot == 6) outValue = vec4(texelFetch(gDepth, probePixel, 0).r, 0.0, 0.0, 0.0);
#endif
    else outValue = vec4(0.0);
}
