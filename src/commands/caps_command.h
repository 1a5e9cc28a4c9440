// `oasis caps [--json]`: what the driver offers (version, strings, limits, extensions) and, for
// each feature oasis can use, whether it is used on this context and why not when not.
#pragma once
#include "cli/options.h"

namespace oasis {

int runCapsCommand(const Options& options);

}  // namespace oasis
