// `compare --json`: the one JSON object compare prints (docs/command-line.md lists its keys).
#pragma once
#include "cli/options.h"
#include "commands/comparison.h"

namespace oasis {

void printCompareJson(const Options& options, const RenderSession& session, const Comparison& c);

}  // namespace oasis
