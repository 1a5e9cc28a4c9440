// The frame's targets' lifetimes from the frame graph (issue 43 item 1): the first and last running
// step that touches each target, by the passes' declarations; render/target_aliasing.h decides
// from them which targets share a texture.
#pragma once
#include <string>
#include <vector>

#include "render/target_aliasing.h"

namespace oasis {

struct FrameGraph;
struct FrameSetup;
class FrameTargets;

// For every target a running step of the frame touches (not the views' after it), at each scale
// it is touched at (the reduced reflection's at 1/2 or 1/4): its first and last step. A target in `beyondFrame` (the frame's sink,
// what code after the frame writes; at the frame's size) lives to kBeyondFrame, and from the first
// step where no step touches it, so it never lends its memory.
std::vector<TargetLifetime> targetLifetimes(const FrameGraph& graph, const FrameSetup& frame,
                                            const std::vector<Target>& beyondFrame);

// Lines that open with "# " after render --graph's passes: each target of `lifetimes` at 1/divisor
// of the frame with its first and last pass, its size and format, whose memory it uses and who
// takes its memory after it.
std::string targetLifetimesText(const FrameGraph& graph, const std::vector<TargetLifetime>& lifetimes,
                                const FrameTargets& targets, int divisor);
// The memory the targets hold after the frame, every scale's (Display included).
std::string heldTargetMemoryText(const FrameTargets& targets);

}  // namespace oasis
