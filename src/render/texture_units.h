// Which texture unit and uniform-block binding each shader input uses: the one table that both
// the shader library (to bind sampler uniforms after linking) and the passes (to bind textures) read,
// and which frame resource each carries for a pass that declares it reads it (kInputBindings).
#pragma once
#include <array>

#include "common/shared_constants.glsl"
#include "render/frame_resource.h"

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
    kUnitRadiance = 9,           // Radiance, as the tone map and the fused water composite read it
    kUnitShadowMap = 10,         // the sun's cascaded shadow maps (render/shadow_maps.h), bound for the whole frame
    kUnitReflection = 11,        // the frame's Reflection, as the water composite reads it
};
inline constexpr int kTextureUnitCount = 12;

inline constexpr std::array<SamplerBinding, 12> kSamplerBindings{{
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
    {"reflectionTexture", kUnitReflection},
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

// Where a pass reads each frame resource it declares it samples (passes/pass.h's Use::Sample): the
// unit or binding bindDeclaredInputs binds it to before the pass runs, and where the frame's
// validation (frame/input_audit.h) finds reads a pass did not declare. The G-buffer's depth is one
// unit, whether read from the depth-stencil target or from its copy. The light list's uniform
// block array takes the bindings from kLightBlockFirstBinding on, one a block. Not here: the
// terrain's heights and the plants' instances (vertex attributes), the water's rectangle (not a
// frame resource: the context's, bound by the passes that clip to it).
enum class InputSlot { Texture2D, TextureArray, UniformBlock, StorageBlock };
struct InputBinding {
    Resource resource;
    InputSlot slot;
    int binding;
};
inline const std::array<InputBinding, 16> kInputBindings{{
    {Target::Albedo, InputSlot::Texture2D, kUnitAlbedo},
    {Target::Normal, InputSlot::Texture2D, kUnitNormal},
    {Target::Position, InputSlot::Texture2D, kUnitPosition},
    {Target::Info, InputSlot::Texture2D, kUnitInfo},
    {Target::DepthStencil, InputSlot::Texture2D, kUnitDepth},
    {Target::SceneDepth, InputSlot::Texture2D, kUnitDepth},
    {Target::Radiance, InputSlot::Texture2D, kUnitRadiance},
    {Target::Reflection, InputSlot::Texture2D, kUnitReflection},
    // The reflection drawn at 1/2 or 1/4, as ReflectionUpsamplePass reads it (sourceTexture).
    {ScaledTarget{Target::Reflection, 2}, InputSlot::Texture2D, kUnitSource},
    {ScaledTarget{Target::Reflection, 4}, InputSlot::Texture2D, kUnitSource},
    {Buffer::ShadowMaps, InputSlot::TextureArray, kUnitShadowMap},
    {Buffer::LightTiles, InputSlot::StorageBlock, kLightTileStorageBinding},
    {Buffer::LightList, InputSlot::StorageBlock, kLightStorageBinding},
    {Buffer::LightList, InputSlot::StorageBlock, kLightCountStorageBinding},
    {Buffer::LightList, InputSlot::UniformBlock, kLightCountBlockBinding},
    {Buffer::LightList, InputSlot::UniformBlock, kLightBlockFirstBinding},
}};

}  // namespace oasis
