// CPU and GPU terrain agree: shaders/height_probe.frag evaluates terrainHeight() at 4096 points
// over +-3 km (negative coordinates included) and matches src/scene/terrain.cpp: height within
// 1e-4, gradient within the relative tolerance below; for the default and a non-default shape.
#include "gpu_test.h"

namespace oasis::gputest {
namespace {

constexpr int kSide = 64;  // 64 x 64 sample points, one per probe pixel

// Sample points: a jittered grid over [-3000, 3000]^2 plus a few special points in the first row
// (origin, just either side of zero, the default flight's start, far negative corner).
std::vector<glm::vec2> samplePoints() {
    std::vector<glm::vec2> points;
    uint32_t state = 12345u;
    auto random = [&] {  // deterministic LCG in [0, 1)
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1u << 24);
    };
    for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i) {
            float step = 6000.0f / kSide;
            points.emplace_back(-3000.0f + (float(i) + random()) * step, -3000.0f + (float(j) + random()) * step);
        }
    const glm::vec2 special[] = {{0.0f, 0.0f}, {-0.001f, -0.001f}, {0.001f, -0.5f}, {-1.0f, 1.0f},
                                 {210.0f, -120.0f}, {-2999.5f, -2999.5f}, {2999.5f, -1.25f}, {-650.0f, 650.0f}};
    for (size_t k = 0; k < std::size(special); ++k) points[k] = special[k];
    return points;
}

class TerrainHeight : public GpuTest {
protected:
    // Renders a frame with `shape` (uploads FrameBlock), then runs the probe over `points`.
    std::vector<glm::vec3> gpuHeights(const TerrainShape& shape, const std::vector<glm::vec2>& points) {
        SceneSettings scene;
        scene.terrain = shape;
        Renderer renderer(*shaders_, scene);
        renderer.configure(64, 36, layoutNamed("standard"));
        renderer.setPipeline(PipelineKind::Deferred);
        renderer.renderFrame(scene);
        return probeGpuHeights(*shaders_, renderer, points);
    }

    // Height within 1e-4 (absolute, world units): the contract shaders/common/noise.glsl states.
    // Gradient (dh/dx, dh/dz) within 1e-3 relative to its magnitude plus 1e-6 absolute for flat
    // spots: the two sides are meant to be the same float32 arithmetic, so only rounding may differ,
    // while a chain-rule mistake (frequency, octave Jacobian, valley term) is tens of percent off.
    void compare(const TerrainShape& shape, const char* label) {
        std::vector<glm::vec2> points = samplePoints();
        std::vector<glm::vec3> gpu = gpuHeights(shape, points);
        ASSERT_EQ(gpu.size(), points.size());
        double worstHeight = 0.0, worstGradient = 0.0, minHeight = 1e9, maxHeight = -1e9;
        int badHeights = 0, badGradients = 0;
        std::string firstBad;
        for (size_t i = 0; i < points.size(); ++i) {
            glm::vec3 cpu = terrainHeight(shape, points[i]);
            minHeight = std::min(minHeight, double(cpu.x));
            maxHeight = std::max(maxHeight, double(cpu.x));
            double heightError = std::fabs(double(gpu[i].x) - cpu.x);
            double gradientError = glm::length(glm::dvec2(gpu[i].y - cpu.y, gpu[i].z - cpu.z));
            double gradientScale = glm::length(glm::dvec2(cpu.y, cpu.z));
            worstHeight = std::max(worstHeight, heightError);
            worstGradient = std::max(worstGradient, gradientError / (gradientScale + 1e-3));
            bool heightOk = heightError <= 1e-4;
            bool gradientOk = gradientError <= 1e-3 * gradientScale + 1e-6;
            badHeights += heightOk ? 0 : 1;
            badGradients += gradientOk ? 0 : 1;
            if ((!heightOk || !gradientOk) && firstBad.empty()) {
                char text[256];
                std::snprintf(text, sizeof(text), "at (%.3f, %.3f): cpu (%.6f, %.6f, %.6f) gpu (%.6f, %.6f, %.6f)",
                              points[i].x, points[i].y, cpu.x, cpu.y, cpu.z, gpu[i].x, gpu[i].y, gpu[i].z);
                firstBad = text;
            }
        }
        std::printf("[terrain] %s: heights %.1f..%.1f, worst height error %.3g (%d of %zu points > 1e-4), "
                    "worst gradient error %.3g relative (%d > tolerance)\n",
                    label, minHeight, maxHeight, worstHeight, badHeights, points.size(), worstGradient, badGradients);
        EXPECT_GT(maxHeight - minHeight, 20.0) << "the samples do not span the terrain's relief";
        EXPECT_EQ(badHeights, 0) << label << ": heights off by more than 1e-4; first " << firstBad;
        EXPECT_EQ(badGradients, 0) << label << ": gradients off by more than 1e-3 relative; first " << firstBad;
    }
};

TEST_F(TerrainHeight, GpuMatchesCpuForTheDefaultShape) { compare(TerrainShape{}, "default shape"); }

// The shape reaches the shader through FrameBlock: a different frequency, amplitude, base height
// and octave count must all be followed. One octave keeps every coordinate small (|q| < 11), where
// float32 evaluation is well conditioned, so this holds to 1e-4 independently of the default
// shape's seven octaves (whose finest octave is evaluated at |q| ~ 2000).
TEST_F(TerrainHeight, GpuFollowsTheShapeInFrameBlock) {
    TerrainShape shape;
    shape.frequency = 1.0f / 300.0f;
    shape.amplitude = 65.0f;
    shape.baseHeight = -7.5f;
    shape.octaves = 1;
    compare(shape, "one-octave shape");
}

}  // namespace
}  // namespace oasis::gputest
