// The headless commands: `render`, `compare`, `probe` and the main job (what `oasis` runs with no display).
// Each returns the process exit code: 0 done, 1 a runtime failure (message printed).
#pragma once
#include "cli/options.h"

namespace oasis {

int runRenderCommand(const Options& options);
int runCompareCommand(const Options& options);
int runMainJob(const Options& options);
// Prints every target's value at --at X,Y of the frame (render/pixel_probe.h).
int runProbeCommand(const Options& options);

}  // namespace oasis
