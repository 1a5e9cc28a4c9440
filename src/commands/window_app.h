// The interactive window: the renderer in a GLFW window with a Dear ImGui panel and keys.
#pragma once
#include "cli/options.h"

namespace oasis {

// Returns the exit code: 0 on a normal close, 1 when no window or context could be had.
int runWindowApp(const Options& options);

}  // namespace oasis
