// The headless commands: `render`, `compare`, `probe` and the main job (what `oasis` runs with no display).
// Each returns the process exit code: 0 done, 1 a runtime failure (message printed).
#pragma once
#include <cstdio>
#include <string>

#include "cli/options.h"
#include "frame/renderer.h"
#include "render/image.h"

namespace oasis {

int runRenderCommand(const Options& options);
int runCompareCommand(const Options& options);
int runMainJob(const Options& options);
// Prints every target's value at --at X,Y of the frame (frame/pixel_probe.h).
int runProbeCommand(const Options& options);

// The image `render` writes for its options: the view (or its values through the controls), the
// overlay, and under a single view its legend (with --legend on); `report` gets the value counts.
Image renderedViewImage(const Options& options, Renderer& renderer, std::FILE* report);

// What `oasis render OPTIONS` draws into its PNG, from the session's first frame on: the sink set,
// the programs built, the frame rendered, the view or encoding-error image made (empty with
// --graph). `oasis check` renders every case through it, so that a case's reproduce line is the
// same code. `readAfter`: what the caller reads of the frame after it, besides the view (the
// check's shading oracle): the sink keeps it (FrameViews::setSink's reads).
struct RenderSession;
Image renderRequestedImage(const Options& options, RenderSession& session, std::FILE* report,
                           const std::vector<Resource>& readAfter = {});

// The difference image compare writes: the heat map of a against b (render/image.h, full scale 16
// levels) with a legend strip naming them and giving PSNR, max abs and RMSE. Sizes must agree.
Image differenceImage(const Image& a, const std::string& aName, const Image& b, const std::string& bName);

}  // namespace oasis
