// The bench's depth-convention parts: reversed-z configurations beside the default layout's
// deferred ones, and the depth-precision comparison (positions reconstructed from the depth
// target, as shaders/common/depth.glsl does, against the full layout's stored float positions)
// in three distance bands taken from the scene.
#pragma once
#include <string>
#include <vector>

#include "bench/bench_report.h"
#include "frame/renderer.h"

namespace oasis {

// After each deferred configuration of `layout`, the same with each convention in `extraDepths`.
void insertDepthConfigs(std::vector<BenchConfig>& configs, const std::string& layout,
                        const std::vector<std::string>& extraDepths);

// Distances [from, to) from the camera, from the scene: near from the near plane to where plants
// start thinning (plants drawn in full), middle to the plants' draw distance, far to the view
// distance (terrain only, up to where its grid ends).
struct DepthBand {
    std::string name;
    double from = 0.0, to = 0.0;
};
std::vector<DepthBand> depthBands(const SceneSettings& scene);

// The camera-relative position relativePositionFromDepth (shaders/common/depth.glsl) computes for
// a window depth at screen uv (0..1, pixel centres), in float as the shader does.
glm::vec3 relativePositionFromDepth(const FrameData& frame, glm::vec2 screenUv, float depth);

// One convention in one band: |reconstructed - stored| over the band's pixels, in world units
// and relative to the stored distance.
struct DepthPrecision {
    std::string depth;  // convention name
    DepthBand band;
    size_t pixels = 0;
    double medianAbs = 0.0, maxAbs = 0.0, medianRelative = 0.0, maxRelative = 0.0;
};

// Renders each scene deferred with the renderer's current targets (the full layout: it stores
// float positions) and compares the positions reconstructed from the depth target with the stored
// ones, over terrain and plant pixels (water pixels hold the mirrored scene's positions, the sky none).
std::vector<DepthPrecision> measureDepthPrecision(Renderer& renderer, const std::vector<SceneSettings>& scenes,
                                                  const std::vector<DepthBand>& bands);

std::string depthPrecisionTable(const std::vector<DepthPrecision>& rows);
std::string depthPrecisionJson(const std::vector<DepthPrecision>& rows);  // a JSON list
// bench.json's fields: "depth_precision_note" (what was measured) and "depth_precision" (the list).
std::string depthPrecisionJsonFields(const std::vector<DepthPrecision>& rows);
std::string depthPrecisionCsv(const std::vector<DepthPrecision>& rows);   // header and rows

}  // namespace oasis
