// Which texture unit and uniform-block binding each shader input uses: the one table that both
// the shader library (to bind sampler uniforms after linking) and the passes (to bind textures) read.
#pragma once
#include <array>

#include "common/shared_constants.glsl"

namespace oasis {

struct SamplerBinding {
    const char* uniformName;
    int unit;
};

enum TextureUnit : int {
    kUnitAlbedo = 0,
    kUnitNormal = 1,
    kUnitPosition = 2,
    kUnitInfo = 3,
    kUnitDepth = 4,
    kUnitStencil = 5,
    kUnitSource = 6,
    kUnitPlantAtlas = 7,
    kUnitProbeDepthStencil = 8,  // the probe's view of the depth-stencil target (compact's gDepth is the copy)
    kUnitRadiance = 9,           // the fused water composite's view of what lies under the water
    kUnitShadowMap = 10,         // the sun's cascaded shadow maps (render/shadow_maps.h), bound for the whole frame
};

inline constexpr std::array<SamplerBinding, 11> kSamplerBindings{{
    {"gAlbedo", kUnitAlbedo},
    {"gNormal", kUnitNormal},
    {"gPosition", kUnitPosition},
    {"gInfo", kUnitInfo},
    {"gDepth", kUnitDepth},
    {"gStencil", kUnitStencil},
    {"sourceTexture", kUnitSource},
    {"plantAtlas", kUnitPlantAtlas},
    {"probeDepthStencil", kUnitProbeDepthStencil},
    {"radianceTexture", kUnitRadiance},
    {"shadowMap", kUnitShadowMap},
}};

inline constexpr const char* kFrameBlockName = "FrameBlock";
inline constexpr int kFrameBlockBinding = 0;

// The point lights (shaders/common/lights.glsl): the UBO path's count block and its block array
// (LightBlock[k] at kLightBlockFirstBinding + k), and the SSBO paths' storage blocks. The storage
// bindings stay below 8, the GL 4.3 minimum of GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS.
inline constexpr const char* kLightCountBlockName = "LightCountBlock";
inline constexpr int kLightCountBlockBinding = 1;
inline constexpr const char* kLightBlockName = "LightBlock";
inline constexpr int kLightBlockFirstBinding = 2;
inline constexpr const char* kLightStorageName = "LightBuffer";
inline constexpr int kLightStorageBinding = OASIS_BINDING_LIGHTS;
// The tiled light method's per-tile lists (shaders/common/light_tiles.glsl), bound by its pass.
inline constexpr const char* kLightTileStorageName = "LightTileBuffer";
inline constexpr int kLightTileStorageBinding = OASIS_BINDING_LIGHT_TILES;
inline constexpr const char* kLightCountStorageName = "LightCountBuffer";
inline constexpr int kLightCountStorageBinding = OASIS_BINDING_LIGHT_COUNT;
// The screen rectangle of the frame's visible water (shaders/common/water_bounds.glsl): its own
// binding, as the tiled mirrored lighting reads it beside the tile lists.
inline constexpr const char* kWaterBoundsStorageName = "WaterBoundsBuffer";
inline constexpr int kWaterBoundsStorageBinding = OASIS_BINDING_WATER_BOUNDS;

}  // namespace oasis
