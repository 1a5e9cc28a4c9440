// What the water tests share (water_test.cpp, water_hard_case_test.cpp): a frame's targets read
// back, the CPU checks of the sky and of the reflection, and the flooded scene.
#pragma once
#include <cstring>
#include <functional>

#include "gpu_test.h"

#include "sky_model.h"

namespace oasis::gputest {


// Everything a frame leaves behind, read back (colour targets bottom row first).
struct FrameReadback {
    int width = 0, height = 0;
    FrameSetup frame;
    std::vector<float> albedo, normal, position, info, radiance, reflection, final, depth;
    std::vector<uint8_t> stencil;

    size_t index(int x, int y) const { return size_t(y) * size_t(width) + size_t(x); }
    glm::vec3 rgb(const std::vector<float>& target, int x, int y) const { return rgbAt(target, width, x, y); }
    unsigned flags(int x, int y) const { return infoFlags(texel(info, width, x, y)); }
    uint8_t stencilAt(int x, int y) const { return stencil[index(x, y)]; }
};

// Not const: reading Radiance after a fused frame lays the water on first (FrameViews::ensureRadiance).
inline FrameReadback readBack(Renderer& renderer, bool gbuffer) {
    FrameReadback r;
    r.width = renderer.targets().width();
    r.height = renderer.targets().height();
    r.frame = renderer.lastFrame().setup;
    if (gbuffer) {
        r.albedo = readTarget(renderer, Target::Albedo);
        r.normal = readTarget(renderer, Target::Normal);
        r.position = readTarget(renderer, Target::Position);
        r.info = readTarget(renderer, Target::Info);
    }
    r.radiance = readTarget(renderer, Target::Radiance);
    r.reflection = readTarget(renderer, Target::Reflection);
    r.final = readTarget(renderer, Target::Final);
    r.depth = readDepth(renderer);
    r.stencil = readStencil(renderer);
    return r;
}

inline FrameReadback renderAndRead(Renderer& renderer, const SceneSettings& scene, PipelineKind kind,
                            const std::string& stopBefore = {}) {
    renderer.setPipeline(kind);
    renderer.renderFrame(scene, stopBefore);
    return readBack(renderer, kind == PipelineKind::Deferred);
}

inline size_t countNonZero(const std::vector<float>& values) {
    return size_t(std::count_if(values.begin(), values.end(), [](float v) { return v != 0.0f; }));
}

inline int countStencil(const FrameReadback& r, uint8_t value) {
    return int(std::count(r.stencil.begin(), r.stencil.end(), value));
}

inline double smoothstep(double e0, double e1, double x) {
    double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Largest channel difference relative to the reference's largest channel (floor `floor`).
inline double relativeError(glm::dvec3 got, glm::dvec3 want, double floor = 1e-3) {
    glm::dvec3 d = glm::abs(got - want);
    return std::max({d.x, d.y, d.z}) / std::max({want.x, want.y, want.z, floor});
}

inline double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0.0;
    size_t k = std::min(values.size() - 1, size_t(p * double(values.size())));
    std::nth_element(values.begin(), values.begin() + long(k), values.end());
    return values[k];
}

// Bilinear sample of an RGBA float target at window coordinates (pixel centres at i + 0.5), only
// where all four texels satisfy `use`; otherwise the nearest texel (`bilinear` says which).
inline glm::dvec3 sampleAt(const FrameReadback& r, const std::vector<float>& target, double wx, double wy,
                    const std::function<bool(int, int)>& use, bool* bilinear = nullptr) {
    int x0 = int(std::floor(wx - 0.5)), y0 = int(std::floor(wy - 0.5));
    double fx = wx - 0.5 - x0, fy = wy - 0.5 - y0;
    bool ok = x0 >= 0 && y0 >= 0 && x0 + 1 < r.width && y0 + 1 < r.height && use(x0, y0) && use(x0 + 1, y0) &&
              use(x0, y0 + 1) && use(x0 + 1, y0 + 1);
    if (bilinear) *bilinear = ok;
    if (!ok) {
        int x = std::clamp(int(std::floor(wx)), 0, r.width - 1), y = std::clamp(int(std::floor(wy)), 0, r.height - 1);
        return glm::dvec3(r.rgb(target, x, y));
    }
    auto at = [&](int x, int y) { return glm::dvec3(r.rgb(target, x, y)); };
    return glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), fx), glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), fx), fy);
}

inline bool onScreen(const FrameReadback& r, glm::dvec3 window) {
    return window.x >= 0.0 && window.y >= 0.0 && window.x < r.width && window.y < r.height;
}

// The CPU sky model against the direct sky (stencil 0) of a frame whose camera is above the water:
// Radiance there is skyRadiance(ray) and nothing else. Returns the worst relative error.
inline double checkSkyModel(const FrameReadback& r, const char* label) {
    const FrameData& f = r.frame.data;
    double worst = 0.0;
    int checked = 0;
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            if (r.stencilAt(x, y) != kStencilSky) continue;
            glm::dvec3 ray = pixelRay(f, r.width, r.height, x, y);
            if (skyIsSensitive(f, ray)) continue;
            worst = std::max(worst, relativeError(glm::dvec3(r.rgb(r.radiance, x, y)), skyRadianceCpu(f, ray)));
            ++checked;
        }
    std::printf("[water] %s: CPU sky model vs direct sky: %d px, worst relative error %.2e\n", label, checked, worst);
    EXPECT_GT(checked, 0) << label << ": no direct sky to check the CPU sky model on";
    // RGBA16F rounding (2^-11 relative) plus float32 evaluation (pow(up, 0.5) near the horizon).
    EXPECT_LE(worst, 2e-3) << label << ": the CPU port of sky.glsl does not match the direct sky";
    return worst;
}

// Every water pixel whose reflection shows the sky: Reflection == sky along the mirrored ray.
struct SkyReflectionStats {
    int checked = 0, sensitive = 0, wrong = 0;
    double worst = 0.0;
    std::string first;
};
inline SkyReflectionStats checkSkyReflection(const FrameReadback& r, const std::function<bool(int, int)>& showsSky) {
    const FrameData& f = r.frame.data;
    SkyReflectionStats stats;
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            if (r.stencilAt(x, y) != kStencilWater || !showsSky(x, y)) continue;
            glm::dvec3 ray = pixelRay(f, r.width, r.height, x, y);
            glm::dvec3 mirrored(ray.x, -ray.y, ray.z);
            if (skyIsSensitive(f, mirrored)) {
                ++stats.sensitive;
                continue;
            }
            double error = relativeError(glm::dvec3(r.rgb(r.reflection, x, y)), skyRadianceCpu(f, mirrored));
            ++stats.checked;
            stats.worst = std::max(stats.worst, error);
            if (error > 2e-3 && stats.wrong++ == 0) {
                char text[160];
                std::snprintf(text, sizeof(text), "(%d, %d from bottom): relative error %.3g", x, y, error);
                stats.first = text;
            }
        }
    return stats;
}

// Reflection is zero wherever the water is not the nearest surface.
inline int reflectionOutsideWater(const FrameReadback& r) {
    int count = 0;
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x)
            if (r.stencilAt(x, y) != kStencilWater && r.rgb(r.reflection, x, y) != glm::vec3(0.0f)) ++count;
    return count;
}

// The water raised to 20 floods the valleys out to the far hills (a level other than 0) and the
// fog is brought in (20 to 1000 units) so the far water is fogged; still water, default absorption.
inline SceneSettings floodedScene() {
    SceneSettings scene = sceneAtHeight(435.0, 40.0, 140.0, 30.0f, -2.0f);
    scene.water.level = 20.0f;
    scene.water.rippleStrength = 0.0f;
    scene.fogStart = 20.0f;
    scene.viewDistance = 1000.0f;
    return scene;
}

inline SceneSettings sceneNamed(const std::string& name) { return name == "flooded" ? floodedScene() : poseNamed(name).scene; }

}  // namespace oasis::gputest
