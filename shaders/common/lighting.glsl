// The lighting both pipelines use: the sun (Lambert diffuse, normalised Blinn-Phong specular
// from the surface's power and intensity), hemisphere ambient from sky and ground, then fog.
#ifndef OASIS_LIGHTING_GLSL
#define OASIS_LIGHTING_GLSL
#include "common/sky.glsl"

vec3 shadeSurface(Surface s) {
    vec3 n = normalize(s.normal);
    vec3 toCamera = normalize(-s.relativePosition);
    vec3 toSun = frame.sunDirection.xyz;
    float diffuse = max(dot(n, toSun), 0.0);
    vec3 halfway = normalize(toSun + toCamera);
    float normalisation = (s.specularPower + 8.0) / 25.13274;  // (p + 8) / (8 pi)
    float specular = diffuse > 0.0
        ? s.specularIntensity * normalisation * pow(max(dot(n, halfway), 0.0), s.specularPower) : 0.0;
    vec3 skyAmbient = mix(frame.skyHorizon.rgb, frame.skyZenith.rgb, 0.5);
    vec3 ambient = mix(frame.groundAmbient.rgb, skyAmbient, 0.5 + 0.5 * n.y);
    vec3 lit = s.albedo * (ambient + frame.sunRadiance.rgb * diffuse) + frame.sunRadiance.rgb * specular;
    float distance = length(s.relativePosition);
    float fog = smoothstep(frame.terrainGridCounts.z, frame.terrainGridCounts.w, distance);
    return mix(lit, fogColour(-toCamera), fog);
}

#endif
