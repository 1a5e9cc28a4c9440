// The probe's report, as `oasis probe` prints it and the window's inspector shows it: the pixel's
// values, and on request how it was shaded (--shading) and what each pass wrote there (--history).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "render/pixel_history.h"
#include "render/pixel_probe.h"
#include "render/shading_probe.h"

namespace oasis {

class Renderer;
struct SceneSettings;

struct ProbeReport {
    PixelProbe probe;
    std::optional<std::vector<ShadedSurface>> shading;
    std::optional<std::vector<PassAtPixel>> history;
};

// The probe of (x, y) (0,0 top left) with its shading and history, of the frame `scene` renders
// with the renderer's pipeline: the history's frames first, then the frame the probe and the
// shading read. Leaves that frame rendered.
ProbeReport probeInDepth(Renderer& renderer, const SceneSettings& scene, int x, int y);

std::string reportJson(const ProbeReport& report);  // one JSON object: the probe's, with "shading" and "history"
std::string reportText(const ProbeReport& report);  // lines for people

}  // namespace oasis
