// The inspector's probes of what the window shows: the hovered pixel's and the pins', each read
// from the renderer that drew the pixel shown there (in a split, the side the pixel is on; in a
// difference, both sides); frozen pins keep their values; I asks for the shading and history.
#include "window/window_state.h"

#include <cmath>
#include <cstdio>

namespace oasis {
namespace window {

namespace {

bool inside(glm::ivec2 p, int width, int height) { return p.x >= 0 && p.y >= 0 && p.x < width && p.y < height; }

std::string probeLinePrefix(const std::string& side) { return side.empty() ? "" : "(" + side + ") "; }

std::vector<SideProbe> probeSides(glm::ivec2 pixel, const std::vector<DrawnSide>& sides, const WindowComparison& c,
                                  int width) {
    std::vector<SideProbe> probes;
    for (const DrawnSide& side : sidesShownAt(pixel, sides, c, width))
        probes.push_back({side.name, probePixel(*side.renderer, pixel.x, pixel.y)});
    return probes;
}

}  // namespace

std::vector<DrawnSide> sidesShownAt(glm::ivec2 pixel, const std::vector<DrawnSide>& sides, const WindowComparison& c,
                                    int width) {
    if (sides.size() < 2 || showsDifference(c.mode)) return sides;
    // splitImage: columns from the divider on are side B's.
    bool sideB = pixel.x >= int(std::lround(c.divider * float(width)));
    return {sides[sideB ? 1 : 0]};
}

void probeInDepthWhenAsked(Inspector& inspector, const SceneSettings& scene, const std::vector<DrawnSide>& sides,
                           const WindowComparison& c, int width, int height) {
    if (!inspector.deepRequested) return;
    inspector.deepRequested = false;
    inspector.deep.clear();
    std::vector<std::pair<size_t, glm::ivec2>> pixels;  // (pin number - 1, pixel)
    for (size_t i = 0; i < inspector.pinned.size(); ++i) pixels.push_back({i, inspector.pinned[i]});
    if (pixels.empty() && inspector.hovered) pixels.push_back({Inspector::kHovered, *inspector.hovered});
    for (const auto& [pin, pixel] : pixels) {
        if (!inside(pixel, width, height)) continue;
        for (const DrawnSide& side : sidesShownAt(pixel, sides, c, width)) {
            ProbeReport report = probeInDepth(*side.renderer, scene, pixel.x, pixel.y);
            std::string which = pin == Inspector::kHovered ? "under the cursor" : "#" + std::to_string(pin + 1);
            std::printf("oasis: probe in depth %s %s%s\n", which.c_str(), probeLinePrefix(side.name).c_str(),
                        reportJson(report).c_str());
            inspector.deep.push_back({pin, side.name, scene.timeSeconds, std::move(report)});
        }
    }
    if (pixels.empty()) std::printf("oasis: probe in depth: nothing pinned or under the cursor\n");
    std::fflush(stdout);
}

void probeShownPixels(Inspector& inspector, const std::vector<DrawnSide>& sides, const WindowComparison& c, int width,
                      int height) {
    // Probing a forward frame fills its G-buffer first: only while the panel shows the probes, or P asks.
    inspector.hoveredProbes.clear();
    if (inspector.hovered && inside(*inspector.hovered, width, height) && (inspector.sectionOpen || inspector.printHovered))
        inspector.hoveredProbes = probeSides(*inspector.hovered, sides, c, width);
    if (inspector.printHovered && !inspector.hoveredProbes.empty()) {
        for (const SideProbe& probe : inspector.hoveredProbes)
            std::printf("oasis: probe %s%s\n", probeLinePrefix(probe.side).c_str(), probeJson(probe.probe).c_str());
        std::fflush(stdout);
        inspector.printHovered = false;
    }
    // Pins: one entry each, in their order (empty where the pixel is outside the frame now).
    std::vector<std::vector<SideProbe>>& pinned = inspector.pinnedProbes;
    if (!inspector.frozen) pinned.clear();
    pinned.resize(std::min(pinned.size(), inspector.pinned.size()));
    if (inspector.sectionOpen)
        for (size_t i = pinned.size(); i < inspector.pinned.size(); ++i)
            pinned.push_back(inside(inspector.pinned[i], width, height) ? probeSides(inspector.pinned[i], sides, c, width)
                                                                        : std::vector<SideProbe>{});
    // Shading and history of pins that are gone go with them.
    std::vector<Inspector::Deep>& deep = inspector.deep;
    for (size_t i = deep.size(); i-- > 0;)
        if (deep[i].pin != Inspector::kHovered && deep[i].pin >= inspector.pinned.size()) deep.erase(deep.begin() + long(i));
}

void printPins(const Inspector& inspector, const std::string& what) {
    for (size_t i = 0; i < inspector.pinnedProbes.size(); ++i)
        for (const SideProbe& pin : inspector.pinnedProbes[i])
            std::printf("oasis: %s #%zu %s%s\n", what.c_str(), i + 1, probeLinePrefix(pin.side).c_str(),
                        probeJson(pin.probe).c_str());
    std::fflush(stdout);
}

}  // namespace window
}  // namespace oasis
