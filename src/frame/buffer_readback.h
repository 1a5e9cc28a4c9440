// The frame's buffers (passes/pass.h's Buffer) read back as the shaders read them: the light list
// through the frame's own light path, the tile lists in common/light_tiles.glsl's layout, the
// plants' instances. The check's pass-by-pass search (check/check_buffers.h) and the pixel history
// (frame/pixel_history_buffers.h) both read them here.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <epoxy/gl.h>

#include "common/shared_constants.glsl"
#include "frame/frame_graph.h"  // kFrameInputsStep

namespace oasis {

class Renderer;
struct FrameSetup;

// A buffer's bytes from `offset` on, `bytes` of them, as the GL holds them (also on OpenGL ES and
// in the page); empty where the buffer is smaller.
std::vector<uint8_t> readBufferBytes(GLuint buffer, size_t offset, size_t bytes);
std::vector<uint32_t> bufferWords(const std::vector<uint8_t>& bytes);
std::vector<float> bufferFloats(const std::vector<uint8_t>& bytes);

// A point light as the buffers hold it: position and radius, colour and intensity (camera-relative).
inline constexpr size_t kLightFloats = 8;
// The lights as the frame's own light path reads them (lightCount(), lightAt(i) of
// common/lights.glsl, drawn out by lights_decode.frag), kLightFloats each; a list longer than the
// count the shaders see is cut to it. False where the context cannot draw into a float target
// (OpenGL ES without EXT_color_buffer_float): the lights are then unknown, not none.
bool readLightsAsShadersSee(Renderer& renderer, std::vector<float>& lights);
// The lights the CPU uploaded for the frame, kLightFloats each.
std::vector<float> uploadedLights(const FrameSetup& frame);
// Whether `light` reaches the camera-relative point `p`: nearer than its radius times `radiusScale`
// (the lighting's rule, common/lights.glsl, at 1).
bool lightReaches(const float* light, const float* p, float radiusScale = 1.0f);

// The plants' instances as stored, direct then mirrored, kPlantInstanceFloats each.
std::vector<float> readPlantInstances(const Renderer& renderer);
size_t plantInstanceFloats();

// The tile lists' layout (common/light_tiles.glsl): per tile its surfaces' nearest and farthest
// distance (float bits), then per slice a count (the true one, even past the maximum) and the list.
inline constexpr size_t kLightSliceWords = OASIS_LIGHT_TILE_MAX_LIGHTS + 1;
inline constexpr size_t kLightTileWords = 2 + OASIS_LIGHT_TILE_SLICES * kLightSliceWords;
// The tile of GL pixel (glX, glY) in a frame `width` pixels wide (lightTileOf).
size_t lightTileOf(int glX, int glY, int width);
// Where a surface `distance` from the camera falls in a tile's range, in slices, and its slice
// (lightSlicePosition, lightSliceOf: clamped as a float first, a tile without surfaces has its
// nearest at 3e38).
float lightSlicePosition(float distance, float nearest, float farthest);
int lightSliceOf(float slicePosition);
// The words of `tiles` tiles from tile `first` of a tile-list buffer; empty where it holds fewer.
std::vector<uint32_t> readLightTiles(GLuint buffer, size_t first, size_t tiles);
// One tile of such words, from `tile`, the first of its words.
struct LightTileWords {
    const uint32_t* tile;
    float nearest() const;
    float farthest() const;
    uint32_t count(int slice) const;  // the true number of lights reaching the slice's surfaces
    // The slice's listed lights (up to the maximum), and whether it lists `light`.
    std::vector<uint32_t> lights(int slice) const;
    bool lists(int slice, uint32_t light) const;
};

}  // namespace oasis
