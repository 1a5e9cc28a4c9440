// The shading oracle's result as text: the `oracle` object of a case in report.json (also how a
// check child hands it to its parent), read back, and the one line report.html shows per case.
#pragma once
#include <string>

#include "commands/json_value.h"
#include "check/shading_oracle.h"

namespace oasis {

// {"pixels_checked", "pixels_sampled", "left_out": {kind: count}, "max_relative_error", "bound",
// "verdict", "differing_term" (failing), "detail", "inputs"}; "null" where the oracle did not run.
std::string shadingOracleJson(const ShadingOracle& oracle);
ShadingOracle shadingOracleFromJson(const JsonValue& object);
// report.html's line beside "shading oracle": "pass, 143 of 256 sampled pixels checked, max 9.3e-04
// relative per half-float store (bound 1.1e-03); left out: sky 53, ..."
std::string shadingOracleLine(const ShadingOracle& oracle);

}  // namespace oasis
