// Terrain fragments: build the material's surface and emit it (G-buffer or shaded, by variant).
// OUTPUT_HEIGHTS rasterises nothing (its vertices are captured): an empty stage, as linking asks.
#include "common/frame_block.glsl"
#if defined(OUTPUT_HEIGHTS)
void main() {}
#else
#include "common/terrain.glsl"
#include "common/emit_surface.glsl"
#include "common/water_clip_fragment.glsl"

in vec3 vRelativePosition;
in vec3 vNormal;

void main() {
#if defined(MIRRORED)
    const bool reflected = true;
#else
    const bool reflected = false;
#endif
    emitSurface(terrainSurface(vRelativePosition, normalize(vNormal), reflected));
    if (belowWater()) discard;
}
#endif
