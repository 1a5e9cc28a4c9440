// The slots of `oasis probe --shading`: each term shadeSurface (common/lighting.glsl), the water's
// surface (common/water_surface.glsl) and the probe (probe_shading.frag) record, one RGBA float
// texel each. Macros, so one file serves GLSL and C++ (src/frame/shading_probe.cpp names them).
// RECORD_TERM is a no-op outside the probe's SHADING_RECORD variant: the frame's shaders are the same code.
#ifndef OASIS_SHADING_TERMS_GLSL
#define OASIS_SHADING_TERMS_GLSL

// The sun and the eye.
#define OASIS_TERM_TO_SUN 0            // xyz: unit vector towards the sun
#define OASIS_TERM_SUN_RADIANCE 1      // rgb: the sun's radiance above the atmosphere's shadowing
#define OASIS_TERM_TO_CAMERA 2         // xyz: unit vector from the surface to the (mirrored) camera
#define OASIS_TERM_NORMAL 3            // xyz: unit normal; w: N.L (unclamped)
#define OASIS_TERM_SHADOW 4            // x: sun visibility 0..1; y: cascade (-1 none)
#define OASIS_TERM_SUN_AT_SURFACE 5    // rgb: sun radiance x visibility
#define OASIS_TERM_SPECULAR_LOBE 6     // x: max(N.L,0); y: (p+8)/(8 pi); z: N.H; w: specular factor
#define OASIS_TERM_AMBIENT 7           // rgb: hemisphere ambient (sky/ground by n.y)
#define OASIS_TERM_ALBEDO 8            // rgb: linear albedo; w: specular power
#define OASIS_TERM_DIFFUSE_PART 9      // rgb: albedo x sun x max(N.L,0)
#define OASIS_TERM_AMBIENT_PART 10     // rgb: albedo x ambient
#define OASIS_TERM_SPECULAR_PART 11    // rgb: sun x specular factor
#define OASIS_TERM_LIT 12              // rgb: the three parts' sum, at the surface
#define OASIS_TERM_WATER_CROSSED 13    // rgb: transmittance; w: length under water (world units)
#define OASIS_TERM_WATER_SCATTER 14    // rgb: what deep water's scattering adds at full depth
#define OASIS_TERM_AFTER_WATER 15      // rgb: lit x transmittance + scatter x (1 - transmittance)
#define OASIS_TERM_FOG 16              // x: fog weight 0..1; y: eye distance (world units)
#define OASIS_TERM_FOG_COLOUR 17       // rgb
#define OASIS_TERM_SURFACE 18          // rgb: shadeSurface's result: mix(after water, fog colour, fog)
#define OASIS_TERM_LIGHTS 19           // rgb: every point light's share summed, carried to the eye; w: lights reaching
#define OASIS_TERM_RADIANCE 20         // rgb: surface + lights (the frame's Radiance/Reflection here)
#define OASIS_TERM_SKY 21              // rgb: the sky along the view ray (through water from below)
// The water's surface (the composite over what lies under it).
#define OASIS_TERM_WATER_NORMAL 22     // xyz: rippled normal; w: cos(view, normal)
#define OASIS_TERM_FRESNEL 23          // x: Fresnel weight; y: glint factor; z: fog weight; w: F0
#define OASIS_TERM_REFLECTED 24        // rgb: what the water reflects (Reflection, or the sky alone)
#define OASIS_TERM_UNDER 25            // rgb: what lies under the water (the direct scene's radiance)
#define OASIS_TERM_WATER_RESULT 26     // rgb: (F x reflected + glint x sun) x (1 - fog) + (1 - F(1 - fog)) x under
// The tone map.
#define OASIS_TERM_TONE_MAP 27         // rgb: Radiance as stored (half floats); w: exposure
#define OASIS_TERM_DISPLAY 28          // rgb: the display colour 0..1 (Final / 255)
// Each point light's share, carried to the eye: rgb; w: the light's index (up to 8, in list order).
#define OASIS_TERM_FIRST_LIGHT 29
#define OASIS_TERM_LIGHT_SLOTS 8
#define OASIS_SHADING_TERMS 37

#if defined(SHADING_RECORD)
// Each fragment of the record keeps the one term its slot names: no array (lavapipe crashed
// running the record with a dynamically indexed array of terms), one comparison per term.
int recordedSlot = -1;
vec4 recordedTerm = vec4(0.0);
#define RECORD_TERM(slot, value) if ((slot) == recordedSlot) recordedTerm = vec4(value)
#else
#define RECORD_TERM(slot, value)
#endif

#endif
