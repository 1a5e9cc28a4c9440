// The probe's report: the pixel's values, its shading and its history, in one text or JSON object.
#include "commands/probe_report.h"

#include "frame/renderer.h"

namespace oasis {

ProbeReport probeInDepth(Renderer& renderer, const SceneSettings& scene, int x, int y, const ProbeAsked& asked) {
    ProbeReport report;
    if (asked.history) report.history = pixelHistory(renderer, scene, x, y);
    renderer.renderFrame(scene, asked.stopBefore);
    report.probe = probePixel(renderer, x, y);
    if (asked.shading) report.shading = probeShading(renderer, report.probe);
    return report;
}

std::string reportJson(const ProbeReport& report) {
    std::string json = probeJson(report.probe);  // one object: the parts go in before its closing brace
    if (report.shading) json.insert(json.size() - 1, ", \"shading\": " + shadingJson(*report.shading));
    if (report.history) json.insert(json.size() - 1, ", \"history\": " + historyJson(*report.history));
    return json;
}

std::string reportText(const ProbeReport& report) {
    std::string text = probeText(report.probe);
    if (report.shading) text += shadingText(*report.shading);
    if (report.history) text += historyText(*report.history);
    return text;
}

}  // namespace oasis
