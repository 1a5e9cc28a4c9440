// The frame's resources as passes name them in their declarations (passes/pass.h): its targets
// (render/gbuffer_layout.h's Target) and the buffers passes hand each other.
#pragma once
#include <string>
#include <variant>

#include "render/gbuffer_layout.h"

namespace oasis {

// The buffers passes hand each other besides the frame's targets: declared like targets so the
// frame graph sees who produces and who consumes them, and the check's pass-by-pass search reads
// what a pass wrote (check/check_buffers.h). LightList (the point lights, SSBO or UBO) and
// PlantInstances (the billboards' instance attributes) are uploaded by the renderer before the
// first pass: the frame's inputs (frame/frame_graph.h's frameInputs), read by the passes.
enum class Buffer { TerrainHeights, ShadowMaps, LightTiles, LightList, PlantInstances };
const char* bufferName(Buffer buffer);
using Resource = std::variant<Target, Buffer>;
std::string resourceName(const Resource& resource);

}  // namespace oasis
