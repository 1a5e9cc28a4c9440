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

// For every target a running step touches: its first and last step. A target in `beyondFrame` (the
// frame's sink, what code after the frame writes) lives from the first step to kBeyondFrame, even
// where no step touches it, so it never lends its memory. Steps drawn into the reduced reflection's
// own targets (`reducedReflection` and Pass::drawsInReflectionTargets) touch none of the frame's.
std::vector<TargetLifetime> targetLifetimes(const FrameGraph& graph, const FrameSetup& frame,
                                            const std::vector<Target>& beyondFrame, bool reducedReflection);

// Lines that open with "# " after render --graph's passes: each target the frame holds with its
// first and last pass, its size and format, and whose memory it uses; Display where it borrows one;
// then the memory held.
std::string targetLifetimesText(const FrameGraph& graph, const std::vector<TargetLifetime>& lifetimes,
                                const FrameTargets& targets);

}  // namespace oasis
