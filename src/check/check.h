// `oasis check`: a hardware-compatibility verdict. Runs the covering set of cases
// (check/check_cases.h) on this driver, judges each against the repository's reference frames
// and against the driver's own main path (check/check_judge.h), finds the first pass where a
// failing path parts from the main path, and writes oasis-check/report.json and report.html.
// Exit 0 when every case passes or is skipped, 1 when one fails, 2 for bad usage.
#pragma once
#include "cli/options.h"

namespace oasis {

int runCheckCommand(const Options& options);

// Where the reference frames are: $OASIS_CHECK_REFERENCES, else beside the shaders' directory
// (an install's share/oasis/check-references, the source tree's tests/check-references).
std::string findCheckReferences();

// The dimensions and the image rules as the Markdown tables docs/check.md shows (`check --tables`).
std::string checkTablesMarkdown();

}  // namespace oasis
