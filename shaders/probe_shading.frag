// `oasis probe --shading`: how one pixel was shaded, by the frame's own GLSL. Its SHADING_RECORD
// variant turns common/shading_terms.glsl's RECORD_TERM into stores, so shadeSurface, the lights
// and the water's surface record their terms while they compute what the frame computed there;
// fragment i of this 1-row draw writes term i (src/frame/shading_probe.cpp reads them back).
#include "common/frame_block.glsl"
#include "common/gbuffer.glsl"
#include "common/output.glsl"
#include "common/water_surface.glsl"
#if defined(SHADING_LIGHTS)
// Through the frame's light path: the variant's LIGHTS_* define.
#include "common/lights.glsl"
#endif

uniform ivec2 probePixel;       // GL's pixel coordinates, bottom row 0
uniform int probeWater;         // 1: the pixel shows the water's surface (its stencil says so)
uniform int probeMirrored;      // 1: the G-buffer holds the mirrored scene (its sky is the reflected sky)
uniform sampler2D sourceTexture;    // Reflection
uniform sampler2D radianceTexture;  // Radiance, as the frame left it (the tone map's input)
// The point lights' part, recorded first by the SHADING_LIGHTS variant (its own draw). It reads the
// lights through the frame's path, as the forward loop and the volumes do: through the UBO path,
// lavapipe (zink, Mesa 22.3.6) aborts running it ("stack smashing detected" in libvulkan_lvp.so),
// even with no lights and without the sun's shading; oasis refuses that record there (exit 1, the way
// round named: src/frame/shading_probe.cpp) rather than crash.
uniform vec3 probeLights;

layout(location = 0) out vec4 outValue;

#if defined(SHADING_LIGHTS)
// The point lights at the surface in list order, each carried to the eye (what the volumes add
// one by one; the forward loop and the tiled list sum the same shares).
vec3 recordPointLights(Surface s) {
    vec3 transfer = pointLightTransfer(s);
    vec3 sum = vec3(0.0);
    int reaching = 0;
    for (int i = 0; i < lightCount(); ++i) {
        vec3 share = pointLightRadiance(s, lightAt(i));
        sum += share;
        // The k-th light that reaches the surface goes to the k-th light slot (up to their number).
        bool reaches = any(notEqual(share, vec3(0.0)));
        if (reaches && OASIS_TERM_FIRST_LIGHT + reaching == recordedSlot && reaching < OASIS_TERM_LIGHT_SLOTS)
            recordedTerm = vec4(share * transfer, float(i));
        reaching += reaches ? 1 : 0;
    }
    RECORD_TERM(OASIS_TERM_LIGHTS, vec4(sum * transfer, float(reaching)));
    return sum * transfer;
}
#endif

void main() {
    recordedSlot = int(gl_FragCoord.x);
    bool sky = gbufferSkyAt(probePixel);
#if defined(SHADING_LIGHTS)
    if (!sky) recordPointLights(readGBuffer(probePixel));
    outValue = recordedTerm;
#else
    vec3 ray = viewRayDirection((vec2(probePixel) + 0.5) * frame.screen.zw);
    vec3 radiance;
    if (sky) {
        radiance = skySeenAlong(ray, probeMirrored == 1);
    } else {
        Surface s = readGBuffer(probePixel);
        radiance = shadeSurface(s) + probeLights;
    }
    RECORD_TERM(OASIS_TERM_RADIANCE, vec4(radiance, sky ? 1.0 : 0.0));
    if (probeWater == 1) {
        // The plane where this pixel's ray meets it, camera-relative (the composite interpolates it).
        vec3 onWater = ray * ((waterLevel() - frame.cameraPosition.y) / ray.y);
        vec4 water = waterSurface(onWater, texelFetch(sourceTexture, probePixel, 0).rgb);
        RECORD_TERM(OASIS_TERM_UNDER, vec4(radiance, 0.0));
        RECORD_TERM(OASIS_TERM_WATER_RESULT, vec4(water.rgb + (1.0 - water.a) * radiance, water.a));
    }
    vec3 stored = texelFetch(radianceTexture, probePixel, 0).rgb;
    RECORD_TERM(OASIS_TERM_TONE_MAP, vec4(stored, frame.depthRange.w));
    RECORD_TERM(OASIS_TERM_DISPLAY, finalColour(stored));
    outValue = recordedTerm;
#endif
}
