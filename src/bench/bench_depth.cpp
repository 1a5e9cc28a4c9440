// Reversed-z configurations and the depth-precision comparison of `oasis bench`.
#include "bench/bench_depth.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/shared_constants.glsl"
#include "frame/frame_readback.h"
#include "passes/pass.h"
#include "io/decimal_text.h"

namespace oasis {
namespace {

// The far plane's window depth in either convention: nothing drawn there (depthAtFarPlane).
bool atFarPlane(const FrameData& frame, float depth) {
    return frame.depthConvention.x != 0.0f ? depth <= 0.0f : depth >= 1.0f;
}

}  // namespace

void insertDepthConfigs(std::vector<BenchConfig>& configs, const std::string& layout,
                        const std::vector<std::string>& extraDepths) {
    std::vector<BenchConfig> out;
    for (const BenchConfig& config : configs) {
        out.push_back(config);
        if (config.pipeline != PipelineKind::Deferred || config.layout != layout) continue;
        for (const std::string& depth : extraDepths) {
            out.push_back(config);
            out.back().depth = depth;
        }
    }
    configs = std::move(out);
}

std::vector<DepthBand> depthBands(const SceneSettings& scene) {
    double nearPlane = scene.projection.nearPlane, thinning = scene.vegetation.thinningStart;
    double plantsEnd = scene.vegetation.drawDistance, view = scene.viewDistance;
    return {{"near", nearPlane, thinning}, {"middle", thinning, plantsEnd}, {"far", plantsEnd, view}};
}

glm::vec3 relativePositionFromDepth(const FrameData& frame, glm::vec2 screenUv, float depth) {
    float nearPlane = frame.depthRange.x, farPlane = frame.depthRange.y;
    float eye;
    if (frame.depthConvention.x != 0.0f) {
        eye = nearPlane * farPlane / (depth * (farPlane - nearPlane) + nearPlane);
    } else {
        float ndc = depth * 2.0f - 1.0f;
        eye = 2.0f * nearPlane * farPlane / (farPlane + nearPlane - ndc * (farPlane - nearPlane));
    }
    glm::vec4 onNearPlane =
        frame.inverseViewProjection * glm::vec4(screenUv * 2.0f - 1.0f, frame.depthConvention.y, 1.0f);
    return glm::vec3(onNearPlane) / onNearPlane.w * (eye / nearPlane);
}

std::vector<DepthPrecision> measureDepthPrecision(Renderer& renderer, const std::vector<SceneSettings>& scenes,
                                                  const std::vector<DepthBand>& bands) {
    std::vector<std::vector<double>> absolute(bands.size()), relative(bands.size());
    renderer.setPipeline(PipelineKind::Deferred);
    const int width = renderer.targets().width(), height = renderer.targets().height();
    for (const SceneSettings& scene : scenes) {
        renderer.renderFrame(scene);
        const FrameData& frame = renderer.lastFrame().setup.data;
        std::vector<float> stored = readTarget(renderer, Target::Position);
        std::vector<float> depth = readDepth(renderer);
        std::vector<uint8_t> stencil = readStencil(renderer);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                size_t i = size_t(y) * size_t(width) + size_t(x);
                int mark = stencil[i] & 0x7F;
                if ((mark != kStencilTerrain && mark != kStencilVegetation) || atFarPlane(frame, depth[i])) continue;
                glm::vec3 truth(stored[4 * i], stored[4 * i + 1], stored[4 * i + 2]);
                glm::vec2 uv((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height));
                double distance = glm::length(glm::dvec3(truth));
                double error = glm::length(glm::dvec3(relativePositionFromDepth(frame, uv, depth[i])) - glm::dvec3(truth));
                for (size_t b = 0; b < bands.size(); ++b)
                    if (distance >= bands[b].from && distance < bands[b].to) {
                        absolute[b].push_back(error);
                        relative[b].push_back(error / distance);
                    }
            }
    }
    std::vector<DepthPrecision> rows;
    for (size_t b = 0; b < bands.size(); ++b) {
        DepthPrecision row;
        row.depth = renderer.paths().depth->name;
        row.band = bands[b];
        row.pixels = absolute[b].size();
        row.medianAbs = median(absolute[b]);
        row.medianRelative = median(relative[b]);
        if (!absolute[b].empty()) {
            row.maxAbs = *std::max_element(absolute[b].begin(), absolute[b].end());
            row.maxRelative = *std::max_element(relative[b].begin(), relative[b].end());
        }
        rows.push_back(row);
    }
    return rows;
}

std::string depthPrecisionTable(const std::vector<DepthPrecision>& rows) {
    std::string text;
    char line[256];
    std::snprintf(line, sizeof(line), "%-11s %-7s %-17s %8s %11s %11s %11s %11s\n", "depth", "band", "distance",
                  "pixels", "median abs", "max abs", "median rel", "max rel");
    text += line;
    for (const DepthPrecision& r : rows) {
        std::string range = formatNumber("%.2f", r.band.from) + "-" + formatNumber("%.0f", r.band.to);
        std::snprintf(line, sizeof(line), "%-11s %-7s %-17s %8zu %11.3e %11.3e %11.3e %11.3e\n", r.depth.c_str(),
                      r.band.name.c_str(), range.c_str(), r.pixels, r.medianAbs, r.maxAbs, r.medianRelative,
                      r.maxRelative);
        text += line;
    }
    return text;
}

std::string depthPrecisionJson(const std::vector<DepthPrecision>& rows) {
    std::string json = "[";
    for (size_t i = 0; i < rows.size(); ++i) {
        const DepthPrecision& r = rows[i];
        json += std::string(i ? ",\n  " : "\n  ") + "{\"depth\": " + jsonString(r.depth) + ", \"band\": " +
                jsonString(r.band.name) + ", \"from\": " + jsonNumber(r.band.from, 3) + ", \"to\": " +
                jsonNumber(r.band.to, 3) + ", \"pixels\": " + std::to_string(r.pixels) +
                ", \"median_abs\": " + formatNumber("%.6e", r.medianAbs) + ", \"max_abs\": " + formatNumber("%.6e", r.maxAbs) +
                ", \"median_relative\": " + formatNumber("%.6e", r.medianRelative) +
                ", \"max_relative\": " + formatNumber("%.6e", r.maxRelative) + "}";
    }
    return json + "\n]";
}

std::string depthPrecisionJsonFields(const std::vector<DepthPrecision>& rows) {
    return "\"depth_precision_note\": \"deferred, full layout (float camera-relative positions: the truth), "
           "default knobs, the first size's frames: positions reconstructed on the CPU from the depth target as "
           "common/depth.glsl does (in float), |reconstructed - stored| over terrain and plant pixels, absolute "
           "(world units) and relative to the distance; bands by distance from the camera [from, to)\", "
           "\"depth_precision\": " + depthPrecisionJson(rows);
}

std::string depthPrecisionCsv(const std::vector<DepthPrecision>& rows) {
    std::string csv = "depth,band,from,to,pixels,median_abs,max_abs,median_relative,max_relative\n";
    for (const DepthPrecision& r : rows)
        csv += r.depth + "," + r.band.name + "," + formatNumber("%.3f", r.band.from) + "," + formatNumber("%.3f", r.band.to) +
               "," + std::to_string(r.pixels) + "," + formatNumber("%.6e", r.medianAbs) + "," + formatNumber("%.6e", r.maxAbs) +
               "," + formatNumber("%.6e", r.medianRelative) + "," + formatNumber("%.6e", r.maxRelative) + "\n";
    return csv;
}

}  // namespace oasis
