// The probe's report, as `oasis probe` prints it and the window's inspector shows it: the pixel's
// values, and on request how it was shaded (--shading) and what each pass wrote there (--history).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "frame/pixel_history.h"
#include "frame/pixel_probe.h"
#include "frame/shading_probe.h"

namespace oasis {

class Renderer;
struct SceneSettings;

struct ProbeReport {
    PixelProbe probe;
    std::optional<std::vector<ShadedSurface>> shading;
    std::optional<std::vector<PassAtPixel>> history;
};

// What a probe reports besides the pixel's values, and of which frame.
struct ProbeAsked {
    bool shading = true;
    bool history = true;
    std::string stopBefore;  // the frame the probe and the shading read ends before this pass
};

// The probe of (x, y) (0,0 top left), with what `asked` adds, of the frame `scene` renders with the
// renderer's pipeline: the history's frames first (its last one scissors a pass), then the frame
// the probe and the shading read. Leaves that frame rendered.
ProbeReport probeInDepth(Renderer& renderer, const SceneSettings& scene, int x, int y, const ProbeAsked& asked = {});

std::string reportJson(const ProbeReport& report);  // one JSON object: the probe's, with "shading" and "history"
std::string reportText(const ProbeReport& report);  // lines for people

}  // namespace oasis
