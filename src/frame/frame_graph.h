// The frame as a graph derived from the passes' declarations (Pass::accesses): which passes run,
// which are culled and why, whether every read has a writer before it, and whether a pass drew
// into anything it did not declare. Printed by `oasis render --graph`.
#pragma once
#include <string>
#include <vector>

#include "passes/pass.h"

namespace oasis {

struct GraphStep {
    const Pass* pass;
    std::vector<Resource> reads, writes;
    bool runs = false;
    std::string culled;  // why it does not run; "" when it runs
};

struct FrameGraph {
    std::vector<GraphStep> steps;
    // Reads with no writer earlier in the frame and no input to hold them: empty when valid.
    std::vector<std::string> problems;
    std::vector<Resource> inputs;  // what holds values before the first pass (frameInputs())
    bool runs(const std::string& passName) const;
};

// What a finished frame is looked at through afterwards when anything may be (the window, the
// probe, a capture, a stopped frame): the sink of a whole frame. Every frame target the
// outputs, views and probe show, the shadow maps and terrain heights they sample; not the depth
// copy or the tile lists, which only passes of the frame read.
std::vector<Resource> frameOutputs();
// What holds values before a fill of a finished frame: everything the frame left.
std::vector<Resource> everyResource();
// The name `render --graph`, the check's pass-by-pass search and the pixel history give the writer
// of the buffers the renderer uploads before the first pass (frameInputs below).
inline constexpr const char* kFrameInputsStep = "(before the passes)";
// What the renderer uploads before a frame's first pass, which its passes then read: the point
// lights (LightList) and the plants' instances (PlantInstances).
std::vector<Resource> frameInputs();

// Culls, walking back from `sinks`, every active pass whose writes no later pass (or sink) reads;
// a Replace write ends what was written before it. Then checks that every read of a running pass
// was written earlier or is one of `inputs`.
FrameGraph buildFrameGraph(const std::vector<const Pass*>& passes, const FrameSetup& frame,
                           const std::vector<Resource>& sinks, const std::vector<Resource>& inputs = {});

// What `passes`, run after a frame to make `sinks` (the views' fill, the composite onto Radiance),
// need the frame to leave: walking back through them by the same rule, the reads that reach
// before the first of them. A view's frame is built for that (FrameViews::setSink).
std::vector<Resource> readsBefore(const std::vector<const Pass*>& passes, const FrameSetup& frame,
                                  const std::vector<Resource>& sinks);

// The graph in order, one pass a line with its reads and writes, culled passes with their reason;
// then, in lines that open with "# ", each buffer the running passes touch with who writes it
// (kFrameInputsStep for an input) and who reads it.
std::string frameGraphText(const FrameGraph& graph);
// The same as a JSON array of {name, reads, writes, culled, reason}.
std::string frameGraphJson(const FrameGraph& graph);

// Whether frames are validated as they run (Pipeline::run): on in debug builds, with
// OASIS_VALIDATE_FRAME=1 in the environment, or where a test switches it on.
bool frameValidation();
void setFrameValidation(bool on);
// The audit after a pass ran: every target attached to the bound draw framebuffer must be one the
// pass declared it writes or tests. Returns what it found wrong, "" when nothing.
std::string auditBoundFramebuffer(const Pass& pass, const PassContext& context);
// The targets, at any scale, that hold `texture` now (several where the plan aliases them).
std::vector<Resource> targetsHolding(const FrameTargets& targets, GLint texture);
// The audit of what the pass bound while it ran (recordBoundTargets, passes/pass.h): every target
// it bound is declared (written, or depth and stencil tested), and every target it declares it
// writes was bound (one the layout stores), so a declaration cannot name a write that never
// happens. Returns what it found wrong, "" when nothing.
std::string auditBoundTargets(const Pass& pass, const PassContext& context, const std::vector<Resource>& bound);

}  // namespace oasis
