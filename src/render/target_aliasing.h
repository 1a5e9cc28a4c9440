// The frame's targets as resources with lifetimes (issue 43 item 1): a target's first and last
// step in the frame, and which targets may share one texture (their lifetimes do not overlap and
// their formats agree). GL-free, so it is unit-tested; frame/target_lifetimes.h derives the
// lifetimes from the frame graph, FrameTargets holds the textures as planned.
#pragma once
#include <array>
#include <climits>
#include <functional>
#include <string>
#include <vector>

#include "render/gbuffer_layout.h"

namespace oasis {

// A lifetime that reaches past the frame: what the frame leaves for its views, or what may be
// written after it (the views' fill, the composite onto Radiance).
constexpr int kBeyondFrame = INT_MAX;

struct TargetLifetime {
    Target target;
    int first, last;  // step indices of the frame graph, inclusive; last may be kBeyondFrame
    int divisor = 1;  // the target at 1/divisor of the frame's size (the reduced reflection's: 2, 4)
};

// For each target of one scale, the target whose memory it uses (itself unless aliased): a later target takes
// the memory of an earlier one whose lifetime ended before it began (strictly: one step cannot
// hold both) and whose format (`formatOf`, 0 = not stored) is the same; a memory is lent to one
// target at a time. Targets without a lifetime map to themselves.
using TargetMemory = std::array<Target, size_t(Target::Count)>;
TargetMemory aliasTargets(const std::vector<TargetLifetime>& lifetimes,
                          const std::function<unsigned(Target)>& formatOf);
TargetMemory unaliasedTargets();

// "albedo 3-16" / "final 8-end" / "final 17-end, memory of albedo": for render --graph.
std::string lifetimeText(const TargetLifetime& lifetime, const TargetMemory& memory);

}  // namespace oasis
