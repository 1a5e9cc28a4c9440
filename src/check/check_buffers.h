// The buffers in the check's pass-by-pass search (check/check_render.h): after each pass, what
// it declares it writes of the buffers (passes/pass.h's Buffer) is read back in a form two paths
// can be compared in, as its targets are: the tile lists checked at each pixel against the lights
// that reach its surface, the light list decoded as the shaders read it, the plants' instances.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "check/check_render.h"
#include "frame/buffer_readback.h"
#include "passes/pass.h"

namespace oasis {

class Renderer;

// Reads what `pass` (the renderer's own, just run) wrote of the buffers `written` into `into`:
// LightTiles as a per-pixel check (lightTileFaults); the other buffers a pass writes (terrain
// heights, shadow maps) are judged by the targets of the passes that read them.
void snapshotWrittenBuffers(Renderer& renderer, const Pass& pass, const std::vector<Resource>& written,
                            PassSnapshot& into);
// The frame's inputs as the last frame uploaded them: LightList decoded through the frame's light
// path's own GLSL (lightCount(), lightAt(i) of common/lights.glsl), so an SSBO and a UBO list that
// the shaders read alike compare equal (left out where the context cannot draw into a float target:
// a buffer one path lacks is not compared); PlantInstances as stored, each instance's 9 floats,
// compared as a multiset. Named kFrameInputsStep.
PassSnapshot snapshotFrameInputs(Renderer& renderer);

// Per pixel (bottom row first, `width` x `height`), how many lights reach the surface there (by
// more than a part in 10^3 of their radius) but are missing from the list of its tile and slice
// in `tileWords` (common/light_tiles.glsl's layout); 0 at sky pixels (position w 0) and where the
// slice's count is over the maximum (the lighting then uses every light). `positions`: the
// G-buffer's camera-relative positions, RGBA; `lights`: 8 floats each (position, radius, colour,
// intensity), camera-relative as uploaded.
std::vector<float> lightTileFaults(const std::vector<uint32_t>& tileWords, const std::vector<float>& positions,
                                   const std::vector<float>& lights, int width, int height);

// How many entries of two decoded buffers differ beyond `level` (levels of 1/255, relative above
// 1): entries of `stride` floats, compared in order or, `unordered`, each sorted first; entries
// one has and the other lacks count too.
long bufferDifferences(const BufferSnapshot& a, const BufferSnapshot& b, int level);

}  // namespace oasis
