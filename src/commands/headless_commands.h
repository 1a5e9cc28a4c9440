// The headless commands: `render`, `compare` and the main job (what `oasis` runs with no display).
// Each returns the process exit code: 0 done, 1 a runtime failure (message printed).
#pragma once
#include "cli/options.h"

namespace oasis {

int runRenderCommand(const Options& options);
int runCompareCommand(const Options& options);
int runMainJob(const Options& options);

}  // namespace oasis
