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
    // A step of the views after the frame (the composite onto Radiance, the views' fill, a debug
    // view): run when the view is drawn, not by Pipeline::run (frame/frame_views.h).
    bool afterFrame = false;
    // A step at or after the pass a stopped frame stops before (--stop-before, cutAt): the graph
    // is the whole frame's, cut there; what would run does not, and the views show what the cut
    // left in the targets.
    bool cut = false;
    // What a reader outside the graph reads right after this step (the check's shading oracle
    // reads the frame as it leaves it, before the views' fill): live there like a sink.
    std::vector<Resource> readAfter = {};
};
// A step of `pass` in `frame`: its reads and writes, not yet culled.
GraphStep graphStep(const Pass& pass, const FrameSetup& frame, bool afterFrame = false);

struct FrameGraph {
    std::vector<GraphStep> steps;
    // Reads with no writer earlier in the frame and no input to hold them: empty when valid.
    std::vector<std::string> problems;
    std::vector<Resource> inputs;  // what holds values before the first pass (frameInputs())
    bool runs(const std::string& passName) const;  // a step of that name runs (and is not cut)
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
// The same over steps already made (graphStep): a request's frame and the views after it.
FrameGraph buildFrameGraph(std::vector<GraphStep> steps, const FrameSetup& frame, const std::vector<Resource>& sinks,
                           const std::vector<Resource>& inputs = {});
// Marks the frame's steps from the one named `passName` on as cut (GraphStep::cut); false when no
// step of the frame is named so.
bool cutAt(FrameGraph& graph, const std::string& passName);
// The graph's steps of the frame itself, without the views' steps after it: what the pixel
// history, the check's buffer search and compare's per-pass JSON walk.
FrameGraph withoutViewSteps(const FrameGraph& graph);

// The line before the views' steps in frameGraphText: they run after the frame, as each view is
// drawn, and end in the displayed image.
inline constexpr const char* kViewStepsHeader =
    "# after the frame, as each view is drawn (the sink: the displayed image)";
// The graph in order, one pass a line with its reads and writes, culled passes with their reason,
// those a stopped frame does not reach with "cut:" (the views' steps after kViewStepsHeader); then, in lines that open with "# ", each buffer the
// running passes touch with who writes it (kFrameInputsStep for an input) and who reads it.
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
