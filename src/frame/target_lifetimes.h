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

// Which running steps a set of targets is drawn by: the frame's (every step, or every step but those
// drawn into the reduced reflection's own targets, Pass::drawsInReflectionTargets) or the reduced
// reflection's (those steps alone).
enum class StepsOf { WholeFrame, FrameWithoutReducedReflection, ReducedReflection };

// For every target a running step of `steps` touches (the frame's, not the views' after it): its
// first and last step. A target in
// `beyondFrame` (the frame's sink, what code after the frame writes) lives to kBeyondFrame, and from
// the first step where no step touches it, so it never lends its memory.
std::vector<TargetLifetime> targetLifetimes(const FrameGraph& graph, const FrameSetup& frame,
                                            const std::vector<Target>& beyondFrame, StepsOf steps);

// Lines that open with "# " after render --graph's passes: each target the frame holds with its
// first and last pass, its size and format, whose memory it uses and who takes its memory after it;
// then the memory held.
std::string targetLifetimesText(const FrameGraph& graph, const std::vector<TargetLifetime>& lifetimes,
                                const FrameTargets& targets);

}  // namespace oasis
