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
// A frame target at a scale of the frame's size, 1/divisor (2 or 4): the reflection drawn at a
// reduced resolution is its targets at that scale (--reflection-resolution half|quarter), other
// resources than the frame's targets of the same name, held by the same FrameTargets.
struct ScaledTarget {
    Target target;
    int divisor;
};
inline bool operator==(const ScaledTarget& a, const ScaledTarget& b) {
    return a.target == b.target && a.divisor == b.divisor;
}
inline bool operator!=(const ScaledTarget& a, const ScaledTarget& b) { return !(a == b); }
inline bool operator<(const ScaledTarget& a, const ScaledTarget& b) {  // for sets of resources
    return a.target != b.target ? a.target < b.target : a.divisor < b.divisor;
}
using Resource = std::variant<Target, Buffer, ScaledTarget, Screen>;
// "reflection", "LightTiles", "reflection at 1/2", "display".
std::string resourceName(const Resource& resource);
// The target of a target resource, at whatever scale, and its divisor (1 for the frame's own);
// false for a buffer.
bool targetOf(const Resource& resource, Target& target, int& divisor);
// `target` at 1/divisor of the frame: the target itself where divisor is 1.
Resource targetAt(Target target, int divisor);

}  // namespace oasis
