// The frame's resources as passes name them in their declarations (passes/pass.h): its targets
// (render/gbuffer_layout.h's Target), the buffers passes hand each other and the displayed image.
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
// The displayed image a request ends in: the Display texture its debug-view pass draws (what the
// headless commands read back, the sink of a request's graph, frame/frame_views.h).
enum class Screen { Display };
using Resource = std::variant<Target, Buffer, Screen>;
std::string resourceName(const Resource& resource);

}  // namespace oasis
