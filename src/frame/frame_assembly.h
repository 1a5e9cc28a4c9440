// The one place a frame's passes are put in order, for every output that draws the scene: the
// frame of either pipeline, the views' fills of the direct or mirrored scene, and the fill of a
// stopped forward frame's G-buffer. Which of them run is the frame graph's (frame/frame_graph.h).
#pragma once
#include <memory>
#include <vector>

#include "passes/pass.h"

namespace oasis {

enum class FrameOutput {
    ForwardFrame,
    DeferredFrame,
    ViewFillDirect,    // the G-buffer, depth and stencil of the direct scene, the water marked
    ViewFillMirrored,  // the same with the mirrored scene inside the water, Reflection kept
    StoppedFrameFill,  // a forward frame stopped early: the deferred steps of the direct scene
};

using PassList = std::vector<std::unique_ptr<Pass>>;
PassList assembleFrame(FrameOutput output);

}  // namespace oasis
