// The lighting both pipelines use: the sun (Lambert diffuse, normalised Blinn-Phong specular
// from the surface's power and intensity) through its shadow maps (common/shadows.glsl),
// hemisphere ambient from sky and ground, then what lies between the surface and the eye: water
// (absorption) and air (fog). Output is linear radiance.
#ifndef OASIS_LIGHTING_GLSL
#define OASIS_LIGHTING_GLSL
#include "common/shading_terms.glsl"
#include "common/shadows.glsl"
#include "common/sky.glsl"
#include "common/surface.glsl"
#include "common/water.glsl"

vec3 reflectAcrossWater(vec3 v) { return vec3(v.x, -v.y, v.z); }

vec3 shadeSurface(Surface s) {
    bool reflected = (s.flags & SURFACE_REFLECTED) != 0u;
    // A reflected surface is lit where it really is and seen from the mirrored camera: the ray
    // from that camera to the surface is the mirror image of the ray to its image.
    vec3 eyeToSurface = reflected ? reflectAcrossWater(s.relativePosition) : s.relativePosition;
    vec3 n = normalize(s.normal);
    vec3 toCamera = normalize(-eyeToSurface);
    vec3 toSun = frame.sunDirection.xyz;
    // The sun as it reaches the surface's real position (the same call in both pipelines).
    SunShadow shadow = sunShadow(litPosition(s), n);
    vec3 sun = frame.sunRadiance.rgb * shadow.lit;
    float diffuse = max(dot(n, toSun), 0.0);
    vec3 halfway = normalize(toSun + toCamera);
    float normalisation = (s.specularPower + 8.0) / 25.13274;  // (p + 8) / (8 pi)
    float specular = diffuse > 0.0
        ? s.specularIntensity * normalisation * pow(max(dot(n, halfway), 0.0), s.specularPower) : 0.0;
    vec3 skyAmbient = mix(frame.skyHorizon.rgb, frame.skyZenith.rgb, 0.5);
    vec3 ambient = mix(frame.groundAmbient.rgb, skyAmbient, 0.5 + 0.5 * n.y);
    vec3 lit = s.albedo * (ambient + sun * diffuse) + sun * specular;
    RECORD_TERM(OASIS_TERM_TO_SUN, vec4(toSun, 0.0));
    RECORD_TERM(OASIS_TERM_SUN_RADIANCE, frame.sunRadiance);
    RECORD_TERM(OASIS_TERM_TO_CAMERA, vec4(toCamera, 0.0));
    RECORD_TERM(OASIS_TERM_NORMAL, vec4(n, dot(n, toSun)));
    RECORD_TERM(OASIS_TERM_SHADOW, vec4(shadow.lit, float(shadow.cascade), 0.0, 0.0));
    RECORD_TERM(OASIS_TERM_SUN_AT_SURFACE, vec4(sun, 0.0));
    RECORD_TERM(OASIS_TERM_SPECULAR_LOBE, vec4(diffuse, normalisation, dot(n, halfway), specular));
    RECORD_TERM(OASIS_TERM_AMBIENT, vec4(ambient, 0.0));
    RECORD_TERM(OASIS_TERM_ALBEDO, vec4(s.albedo, s.specularPower));
    RECORD_TERM(OASIS_TERM_DIFFUSE_PART, vec4(s.albedo * sun * diffuse, 0.0));
    RECORD_TERM(OASIS_TERM_AMBIENT_PART, vec4(s.albedo * ambient, 0.0));
    RECORD_TERM(OASIS_TERM_SPECULAR_PART, vec4(sun * specular, 0.0));
    RECORD_TERM(OASIS_TERM_LIT, vec4(lit, 0.0));
    // Reflections show only what is above the water, so only direct views cross it.
    if (!reflected) {
        vec3 eye = frame.cameraPosition.xyz;
        float under = underwaterLength(eye, eye + s.relativePosition);
        RECORD_TERM(OASIS_TERM_WATER_CROSSED, vec4(exp(-frame.water.y * under * vec3(1.0, 0.45, 0.3)), under));
        RECORD_TERM(OASIS_TERM_WATER_SCATTER, vec4(waterScatter(), 0.0));
        lit = throughWater(lit, under);
    } else {
        RECORD_TERM(OASIS_TERM_WATER_CROSSED, vec4(1.0, 1.0, 1.0, 0.0));
    }
    RECORD_TERM(OASIS_TERM_AFTER_WATER, vec4(lit, 0.0));
    float fog = smoothstep(frame.terrainGridCounts.z, frame.terrainGridCounts.w, length(eyeToSurface));
    RECORD_TERM(OASIS_TERM_FOG, vec4(fog, length(eyeToSurface), 0.0, 0.0));
    RECORD_TERM(OASIS_TERM_FOG_COLOUR, vec4(fogColour(-toCamera), 0.0));
    vec3 shaded = mix(lit, fogColour(-toCamera), fog);
    RECORD_TERM(OASIS_TERM_SURFACE, vec4(shaded, 0.0));
    return shaded;
}

// The sky along a view ray, as seen directly (through water if the camera is under it) or mirrored.
vec3 skySeenAlong(vec3 direction, bool reflected) {
    vec3 sky = reflected ? skyRadiance(reflectAcrossWater(direction))
                         : throughWater(skyRadiance(direction), underwaterLengthToSky(frame.cameraPosition.xyz, direction));
    RECORD_TERM(OASIS_TERM_SKY, vec4(sky, 0.0));
    return sky;
}

// The view ray through a pixel (uv in [0,1]^2), camera-relative world direction.
vec3 viewRayDirection(vec2 uv) {
    vec4 farPoint = frame.inverseViewProjection * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
    return normalize(farPoint.xyz / farPoint.w);
}

// The view ray through this fragment's pixel centre, from gl_FragCoord rather than an interpolated
// varying: the reflection's full-screen triangle is clipped to the water's rectangle where the
// context allows (common/water_bounds.glsl), and a clipped triangle interpolates its varyings with
// other rounding; the clouds magnify the ray's last bits near the horizon into 8-bit steps, so the
// bounded and unbounded frames (every forced fallback) would no longer be equal bit for bit.
// Fragment shaders only (every includer of this file is one).
vec3 viewRayThroughPixel() { return viewRayDirection(gl_FragCoord.xy * frame.screen.zw); }

#endif
