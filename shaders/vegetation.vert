// Plant billboards: one instance per plant, a 4-vertex strip standing on its base, turned about
// the vertical to face the camera (the plants stay upright), its top bent by a wind field: gusts
// of noise drifting with the wind plus each plant's own flutter. The base never moves.
// MIRRORED: the mirror image across the water plane, clipped to what lies above the water; a
// billboard whose image lands wholly outside the visible water is dropped (common/water_bounds.glsl).
// OUTPUT_SHADOW: the same billboard (facing the camera, as drawn) seen from the sun.
#include "common/frame_block.glsl"
#include "common/detail_noise.glsl"
#include "common/shared_constants.glsl"
#include "common/water_clip_vertex.glsl"
#if defined(MIRRORED)
#include "common/water_bounds.glsl"
#endif

layout(location = 0) in vec4 baseSize;   // xyz base minus camera, w billboard height (world units)
layout(location = 1) in vec4 tintPhase;  // rgb tint, w wind phase (radians)
layout(location = 2) in float variant;   // atlas cell

out vec2 vAtlasUv;
out vec3 vRelativePosition;
out vec3 vNormal;
out vec3 vTint;
out float vAtlasLod;
#if defined(OUTPUT_SHADOW)
#include "common/shadow_caster.glsl"
#endif


// Sideways displacement of a plant's top per unit of its height: at most 0.24 * wind strength
// (scene/vegetation.cpp bounds chunks by 0.3 per unit of strength). The gusts are a detail noise
// layer drifting with the wind (its direction and speed are in frame_setup.cpp's layer table).
vec2 windBend(vec2 relativeXZ, float phase) {
    const vec2 windDirection = vec2(0.943, 0.333);  // unit, blowing east-north-east
    float strength = frame.vegetation.x;
    float gust = 0.5 + 0.5 * detailNoise(OASIS_DETAIL_WIND_GUSTS, relativeXZ).x;
    float flutter = sin(frame.vegetation.y + phase);
    return windDirection * strength * (0.18 * gust + 0.06 * flutter);
}

// The billboard's point at `corner` of its atlas cell (0..1 each way), relative to the camera.
vec3 billboardPoint(vec3 base, vec3 right, float size, vec2 bend, vec2 corner) {
    // The atlas cell's root is OASIS_PLANT_ROOT_V above its bottom edge; the base is the root.
    const float rootV = float(OASIS_PLANT_ROOT_V);
    float aboveRoot = (corner.y - rootV) * size;
    vec3 relative = base + right * ((corner.x - 0.5) * size) + vec3(0.0, aboveRoot, 0.0);
    // The cell's top bends by the wind, its bottom edge not; between them the quad is sheared
    // linearly (the whole cell's strip interpolates its corners' bend), so the trimmed strip takes
    // that shear at its own corners: the cell's height fraction.
    relative.xz += bend * size * corner.y;
    return relative;
}

#if defined(MIRRORED)
vec3 mirroredPoint(vec3 relative) {
    return vec3(relative.x, 2.0 * (frame.water.x - frame.cameraPosition.y) - relative.y, relative.z);
}
#endif

void main() {
    vec3 base = baseSize.xyz;
    float size = baseSize.w;
    // The strip's corner (0,0) (1,0) (0,1) (1,1) of the cell, moved in to the drawn bounds; every
    // quantity below is the whole cell's at that point, so the plant is drawn where it was.
    vec4 drawn = frame.plantDrawnBounds[int(variant)];
    vec2 corner = mix(drawn.xy, drawn.zw, vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1)));

    vec2 toCamera = -base.xz;
    float distance = length(toCamera);
    vec2 facing = distance > 1e-4 ? toCamera / distance : vec2(0.0, 1.0);
    vec3 right = vec3(facing.y, 0.0, -facing.x);
    vec2 bend = windBend(base.xz, tintPhase.w);
    vec3 relative = billboardPoint(base, right, size, bend, corner);

    // Lit as a tuft: mostly up, partly towards the camera, so plants take the ground's light.
    vNormal = normalize(vec3(0.0, 1.0, 0.0) + 0.6 * vec3(facing.x, 0.0, facing.y));
    vTint = tintPhase.rgb;
    float columns = frame.vegetationAtlas.x, rows = frame.vegetationAtlas.y;
    float column = mod(variant, columns), row = floor(variant / columns);
    // Cell rows are numbered from the atlas's top, which is GL's high v.
    vAtlasUv = vec2((column + corner.x) / columns, 1.0 - (row + 1.0 - corner.y) / rows);
#if defined(MIRRORED)
    clipAtWater(relative.y + frame.cameraPosition.y - frame.water.x);  // keep what is above the water
    relative = mirroredPoint(relative);
#endif
    vRelativePosition = relative;
    // The camera's clip position picks the mip level below even for the sun's view, so a plant
    // casts the shadow of the billboard the frame draws.
    vec4 cameraClip = frame.viewProjection * vec4(relative, 1.0);
#if defined(OUTPUT_SHADOW)
    gl_Position = shadowCasterPosition(relative);
#else
    gl_Position = cameraClip;
#endif
#if defined(MIRRORED)
    vec4 corners[4];
    for (int i = 0; i < 4; ++i) {
        vec2 other = mix(drawn.xy, drawn.zw, vec2(float(i & 1), float(i >> 1)));
        corners[i] = frame.viewProjection * vec4(mirroredPoint(billboardPoint(base, right, size, bend, other)), 1.0);
    }
    if (billboardMissesWater(corners[0], corners[1], corners[2], corners[3]))
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // every corner outside the clip volume: nothing rasterised
#endif
    // The mip level: atlas texels per screen pixel along the billboard's height. Computed here from
    // the projected size rather than from derivatives in the fragment shader, whose dFdx with the
    // alpha test's discard and the UBO light blocks crashed lavapipe (zink). One level for the
    // whole billboard, taken at its cell's centre: every corner computes the same, so a trimmed
    // strip samples the levels the whole cell would, and no level boundary crawls across a plant.
    vec3 centre = billboardPoint(base, right, size, bend, vec2(0.5));
#if defined(MIRRORED)
    centre = mirroredPoint(centre);
#endif
    float centreW = (frame.viewProjection * vec4(centre, 1.0)).w;
    float texelsPerUnit = frame.vegetationAtlas.z / size;
    float pixelsPerUnit = frame.vegetationAtlas.w / max(centreW, 1e-3);
    vAtlasLod = log2(max(texelsPerUnit / pixelsPerUnit, 1e-6));
}
