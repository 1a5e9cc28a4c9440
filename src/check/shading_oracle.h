// `oasis check`'s shading oracle (issue 40, item 6): at a fixed sample of a shaded case's pixels,
// the driver's Radiance against a CPU evaluation of oasis's shading (check/oracle_shading.h) from
// the primary inputs read back from the driver after the frame: the G-buffer's texels (decoded on
// the CPU), the shadow maps' depths, the light list and the frame's uniform block. A pixel the CPU
// cannot rebuild is left out and counted by kind; a difference beyond the bound names the first
// term that differs, against the terms the shading probe records (used for naming only).
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace oasis {

class Renderer;
struct OracleInputs;

struct ShadingOracle {
    bool ran = false;         // a shaded case: the oracle was evaluated
    int pixelsSampled = 0;    // the seeded sample's size
    int pixelsChecked = 0;
    std::vector<std::pair<std::string, int>> leftOut;  // kind, pixels
    // The largest difference per half-float store of Radiance at a checked pixel (|driver - CPU|
    // over max(|CPU|, 2^-14), channel by channel, divided by the stores the pixel's radiance went
    // through: 1, or 1 + the light volumes blended onto it), and the bound it is held to.
    double maxRelativeError = 0.0;
    double bound = 0.0;
    std::string verdict;        // "pass" or "fail"
    std::string differingTerm;  // failing: the first term that differs ("diffuse_part", "light 3", "radiance")
    std::string detail;         // failing: where and by how much, for people
    std::string inputs;         // where the inputs came from
};

// The relative bound per half-float store (docs/check.md, "A shading oracle").
double shadingOracleBound();

// The oracle over the renderer's last whole frame (deferred or forward), `samples` pixels chosen
// by a fixed seed: three quarters over the frame, a quarter among those the point lights reach. Throws std::runtime_error where an input cannot be read at all.
ShadingOracle runShadingOracle(Renderer& renderer, int samples = 256);
// The same over inputs already read (check/oracle_inputs.h), which the check also splits into edges
// and interiors (check/case_geometry.h): one read of the frame for both.
ShadingOracle runShadingOracle(Renderer& renderer, const OracleInputs& inputs, int samples = 256);

}  // namespace oasis
