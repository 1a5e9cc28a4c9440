// `oasis compare --driver A --driver B` and `--reference FILE.png`: the same frame rendered on two
// driver set-ups of this machine (cli/driver_setups.h), each by a child `oasis render` in that
// set-up's environment, or one frame against a saved PNG (a frame sent from another machine,
// rendered here with the options its provenance carries: commands/provenance.h);
// PSNR / max abs / RMSE and difference.png with its legend, as the pipeline comparison writes.
#pragma once
#include "cli/options.h"

namespace oasis {

// 0 compared; 1 a set-up failed, was killed (by a signal, or at --driver-timeout: its process group),
// or its driver is missing here (said which and why);
// 2 bad input found only now (a reference that is not a readable PNG, whose size differs from --size,
// that is not a final frame alone, or whose provenance's options differ from the scene options given).
int runDriverCompare(const Options& options);

}  // namespace oasis
