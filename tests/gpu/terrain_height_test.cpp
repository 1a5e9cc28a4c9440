// CPU and GPU terrain agree: shaders/height_probe.frag evaluates terrainHeightFromCamera() at
// 4096 points within +-3 km of the camera (negative coordinates included) and matches
// src/scene/terrain.cpp twice over: its float twin of the GPU's arithmetic (same origins, same
// float offsets) within 1e-4 in height and the relative gradient tolerance below, everywhere;
// and the exact reference (every noise coordinate in double) within 1e-4 inside 500 units of the
// camera, the float offset's rounding beyond. Cameras at the default flight, 1e5 and 1e6 units
// out: the errors must not grow with the camera's distance from the world's origin.
#include "gpu_test.h"

namespace oasis::gputest {
namespace {

constexpr int kSide = 64;  // 64 x 64 sample points, one per probe pixel

// Sample points: a jittered grid over the camera's +-3000 square plus, for a camera near the
// origin, a few special points in the first row (origin, just either side of zero, the default
// flight's start, a far corner).
std::vector<glm::dvec2> samplePoints(glm::dvec2 camera) {
    std::vector<glm::dvec2> points;
    uint32_t state = 12345u;
    auto random = [&] {  // deterministic LCG in [0, 1)
        state = state * 1664525u + 1013904223u;
        return double(state >> 8) / double(1u << 24);
    };
    for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i) {
            double step = 6000.0 / kSide;
            points.push_back(camera + glm::dvec2(-3000.0 + (i + random()) * step, -3000.0 + (j + random()) * step));
        }
    if (glm::length(camera) < 1000.0) {
        const glm::dvec2 special[] = {{0.0, 0.0}, {-0.001, -0.001}, {0.001, -0.5}, {-1.0, 1.0},
                                      {210.0, -120.0}, {-2999.5, -2999.5}, {2999.5, -1.25}, {-650.0, 650.0}};
        for (size_t k = 0; k < std::size(special); ++k) points[k] = special[k];
    }
    return points;
}

struct Errors {
    double worstHeight = 0.0, worstGradient = 0.0;
    int badHeights = 0, badGradients = 0;
    std::string firstBad;
    double worstGradientAbs = 0.0;
    double gradientRelative = 1e-3, gradientAbsolute = 1e-6;
    void note(glm::dvec2 at, glm::vec3 cpu, glm::vec3 gpu, double heightTolerance, bool checkGradient) {
        double heightError = std::fabs(double(gpu.x) - cpu.x);
        double gradientError = glm::length(glm::dvec2(gpu.y - cpu.y, gpu.z - cpu.z));
        double gradientScale = glm::length(glm::dvec2(cpu.y, cpu.z));
        worstHeight = std::max(worstHeight, heightError);
        worstGradient = std::max(worstGradient, gradientError / (gradientScale + 1e-3));
        worstGradientAbs = std::max(worstGradientAbs, gradientError);
        bool heightOk = heightError <= heightTolerance;
        bool gradientOk = !checkGradient || gradientError <= gradientRelative * gradientScale + gradientAbsolute;
        badHeights += heightOk ? 0 : 1;
        badGradients += gradientOk ? 0 : 1;
        if ((!heightOk || !gradientOk) && firstBad.empty()) {
            char text[256];
            std::snprintf(text, sizeof(text), "at (%.3f, %.3f): cpu (%.6f, %.6f, %.6f) gpu (%.6f, %.6f, %.6f)", at.x,
                          at.y, cpu.x, cpu.y, cpu.z, gpu.x, gpu.y, gpu.z);
            firstBad = text;
        }
    }
};

class TerrainHeight : public GpuTest {
protected:
    // Renders a frame with `shape` from `camera` (uploads FrameBlock), then probes `points`.
    std::vector<glm::vec3> gpuHeights(const TerrainShape& shape, glm::dvec3 camera,
                                      const std::vector<glm::dvec2>& points) {
        SceneSettings scene;
        scene.terrain = shape;
        scene.camera = CameraPose{camera, 30.0f, -10.0f};
        Renderer renderer(*shaders_, scene);
        renderer.configure(64, 36, layoutNamed("standard"));
        renderer.setPipeline(PipelineKind::Deferred);
        renderer.renderFrame(scene);
        return probeGpuHeights(*shaders_, renderer, points);
    }

    // Twin: the GPU's float arithmetic from the same origins — height within 1e-4 (absolute, world
    // units), gradient (dh/dx, dh/dz) within 1e-3 relative plus 1e-6 absolute for flat spots: only
    // rounding may differ, while a chain-rule mistake (frequency, octave Jacobian, valley term) or a
    // wrong origin is tens of percent off. Reference: every octave's coordinate in double — within
    // 1e-4 near the camera; beyond, the float offset's rounding, allowed 1e-4 + 1e-6 per unit of
    // distance (measured about 3.7e-7 per unit at the default shape's seven octaves).
    void compare(const TerrainShape& shape, glm::dvec2 cameraXZ, const char* label) {
        glm::dvec3 camera(cameraXZ.x, terrainHeight(shape, cameraXZ).x + 30.0, cameraXZ.y);
        std::vector<glm::dvec2> points = samplePoints(cameraXZ);
        std::vector<glm::vec3> gpu = gpuHeights(shape, camera, points);
        ASSERT_EQ(gpu.size(), points.size());
        NoiseOrigins origins = terrainNoiseOrigins(shape, cameraXZ);
        // A GPU's own sin, cos and fused multiply-adds round differently from the twin's float
        // order (H100: heights 5.5e-4 to 1.03e-3 off the twin, while within 8.4e-5 of the exact
        // heights near the camera; gradients 3.2e-4 off at most): the twin's bound there is 2e-3,
        // gradients 1e-2 relative plus 6e-4; still far inside the 0.1 units that VisibleWaterBound
        // keeps dry land above water.
        const bool exactArithmetic = cpuRasteriser();
        const double twinHeightTolerance = exactArithmetic ? 1e-4 : 2e-3;
        Errors twin, exactNear, exactFar;
        if (!exactArithmetic) {
            twin.gradientRelative = 1e-2;
            twin.gradientAbsolute = 6e-4;
        }
        double minHeight = 1e9, maxHeight = -1e9;
        for (size_t i = 0; i < points.size(); ++i) {
            glm::dvec2 offset = points[i] - cameraXZ;
            glm::vec3 mirrored = terrainHeightFromCamera(shape, origins, glm::vec2(offset));
            glm::vec3 exact = terrainHeight(shape, points[i]);
            minHeight = std::min(minHeight, double(exact.x));
            maxHeight = std::max(maxHeight, double(exact.x));
            twin.note(points[i], mirrored, gpu[i], twinHeightTolerance, true);
            double distance = glm::length(offset);
            if (distance < 500.0) exactNear.note(points[i], exact, gpu[i], 1e-4, false);
            else exactFar.note(points[i], exact, gpu[i], 1e-4 + 1e-6 * distance, false);
        }
        std::printf("[terrain] %s, camera (%.0f, %.0f): heights %.1f..%.1f; vs twin worst %.3g (gradient %.3g rel); "
                    "worst gradient %.3g abs; vs exact worst %.3g within 500 units, %.3g beyond\n",
                    label, cameraXZ.x, cameraXZ.y, minHeight, maxHeight, twin.worstHeight, twin.worstGradient, twin.worstGradientAbs,
                    exactNear.worstHeight, exactFar.worstHeight);
        EXPECT_GT(maxHeight - minHeight, 20.0) << "the samples do not span the terrain's relief";
        EXPECT_EQ(twin.badHeights, 0) << label << ": heights off the GPU twin by more than " << twinHeightTolerance << "; first " << twin.firstBad;
        EXPECT_EQ(twin.badGradients, 0) << label << ": gradients off by more than " << twin.gradientRelative << " relative; first " << twin.firstBad;
        EXPECT_GT(exactNear.worstHeight + exactFar.worstHeight, 0.0) << "no samples compared";
        EXPECT_EQ(exactNear.badHeights, 0) << label << ": near heights off the exact ones by more than 1e-4; first "
                                           << exactNear.firstBad;
        EXPECT_EQ(exactFar.badHeights, 0) << label << ": far heights off the exact ones; first " << exactFar.firstBad;
    }
};

TEST_F(TerrainHeight, GpuMatchesCpuForTheDefaultShape) { compare(TerrainShape{}, {210.0, -120.0}, "default shape"); }

// The far lands: 1e5 and 1e6 units out, the camera's noise coordinates are large, but only the
// offsets from the camera are floats, so the same tolerances hold.
TEST_F(TerrainHeight, GpuMatchesCpuFarFromTheOrigin) {
    compare(TerrainShape{}, {1.0e5, -7.0e4}, "default shape, 1e5 out");
    compare(TerrainShape{}, {-6.0e5, 8.0e5}, "default shape, 1e6 out");
}

// The shape reaches the shader through FrameBlock: a different frequency, amplitude, base height
// and octave count must all be followed.
TEST_F(TerrainHeight, GpuFollowsTheShapeInFrameBlock) {
    TerrainShape shape;
    shape.frequency = 1.0f / 300.0f;
    shape.amplitude = 65.0f;
    shape.baseHeight = -7.5f;
    shape.octaves = 1;
    compare(shape, {210.0, -120.0}, "one-octave shape");
}

}  // namespace
}  // namespace oasis::gputest
