// Numbers both C++ and GLSL must agree on, as macros so one file serves both languages
// (C++ includes it through the shaders/ include path).
#ifndef OASIS_SHARED_CONSTANTS_GLSL
#define OASIS_SHARED_CONSTANTS_GLSL

// Terrain height = amplitude * (n + k n^2) + base: flat valleys for the water, sharper ridges.
#define OASIS_TERRAIN_VALLEY_FLATTENING 0.3
// The most octaves the fractal noise sums (FrameData holds an origin per octave).
#define OASIS_NOISE_MAX_OCTAVES 8
// Detail noise layers (single octaves of simplex noise, some drifting with time) evaluated around
// the camera like the terrain: FrameData.detailNoiseOrigins[layer]. Their scales and drifts are
// one table in src/render/frame_setup.cpp.
#define OASIS_DETAIL_RIPPLE_BROAD 0
#define OASIS_DETAIL_RIPPLE_FINE 1
#define OASIS_DETAIL_GROUND_BROAD 2
#define OASIS_DETAIL_GROUND_FINE 3
#define OASIS_DETAIL_WIND_GUSTS 4
#define OASIS_DETAIL_CLOUDS_BROAD 5
#define OASIS_DETAIL_CLOUDS_FINE 6
#define OASIS_DETAIL_ROCK_CRACKS 7
#define OASIS_DETAIL_LAYERS 8
// The cloud deck's world height (common/sky.glsl): clouds are seen from below it only.
#define OASIS_CLOUD_ALTITUDE 1100.0
// Storage block bindings (render/texture_units.h binds them by name on desktop GL; OpenGL ES has no
// glShaderStorageBlockBinding, so there the blocks state them: common/storage_layout.glsl).
#define OASIS_BINDING_WATER_BOUNDS 4
#define OASIS_BINDING_LIGHT_TILES 5
#define OASIS_BINDING_LIGHTS 6
#define OASIS_BINDING_LIGHT_COUNT 7
// The UBO light path's most uniform blocks (lights.glsl indexes them by constants before GLSL 4.00).
#define OASIS_LIGHTS_UBO_MAX_BLOCKS 8
// Tiled light culling (passes/light_tiling_pass.h): square screen tiles of this many pixels, one
// compute invocation each, cut into this many slices by distance from the camera, each slice with
// its list of at most OASIS_LIGHT_TILE_MAX_LIGHTS light indices. A slice reached by more lights
// keeps its true count and is lit from the whole list instead (common/light_tiles.glsl), so no
// light is ever dropped.
#define OASIS_LIGHT_TILE_SIZE 16
#define OASIS_LIGHT_TILE_SLICES 4
#define OASIS_LIGHT_TILE_MAX_LIGHTS 256
// The water plane is a grid of this many cells per side around the camera, drawn as two triangles
// per cell (render/scene_geometry.cpp draws 6 * cells^2 vertices; water.vert places them). Cells
// grow with the square of their distance from the camera, so the ones near it are small: one
// view-wide quad is clipped to a sliver whose depth some rasterisers (SwiftShader) interpolate
// too coarsely, and the water then won the depth test against nearby river banks (docs/web.md).
#define OASIS_WATER_GRID_CELLS 8
// Bit of FrameData.water.w: the mirrored scene is drawn this frame.
#define OASIS_WATER_REFLECTIONS_FLAG 1u
// Set by the renderer when the reflection is bounded to the visible water this frame (--reflection-bounds).
#define OASIS_WATER_BOUNDED_FLAG 2u
// Surface flags stored in the info target, flags / 255 in this channel: b in the layouts that
// store the surface as is, g in the compact layout's two-channel info (common/gbuffer.glsl).
#define OASIS_INFO_FLAGS_CHANNEL 2
#define OASIS_COMPACT_INFO_FLAGS_CHANNEL 1
#define OASIS_SURFACE_SKY 1u
#define OASIS_SURFACE_REFLECTED 2u
#define OASIS_SURFACE_PLANT 4u
// A plant's root sits this fraction of its atlas cell above the cell's bottom edge, centred.
#define OASIS_PLANT_ROOT_V 0.05
// The plant billboards' alpha test keeps a texel whose alpha reaches this, at every mip level: the
// atlas's levels are built to keep each cell's coverage at it (src/render/coverage_mips.h).
#define OASIS_PLANT_ALPHA_THRESHOLD 0.5
// The most atlas cells (plant variants) the billboards' uniform array of drawn bounds holds.
#define OASIS_PLANT_MAX_CELLS 16
// Sun shadows (common/shadows.glsl): the most cascades FrameData holds matrices for; how many a
// frame uses and their map size are one table in src/render/shadow_cascades.cpp.
#define OASIS_SHADOW_MAX_CASCADES 4

#endif
