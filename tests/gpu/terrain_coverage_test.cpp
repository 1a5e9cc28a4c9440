// Terrain coverage: the polar grid (ring radii, the wedge of azimuths) covers every pixel whose
// view ray points more than 20 degrees below the horizon, over a sweep of pitches, yaws and places.
// Reflections are off so that the G-buffer holds the direct terrain at water pixels too (the lake
// bed under the water, e.g. below the camera at (-1150, 1250)); with them on, a water pixel holds
// the mirrored scene, which is the sky for steep rays.
#include "frame/frame_readback.h"
#include "gpu_test.h"

namespace oasis::gputest {
namespace {

// A ray from a camera 10 units above the ground going down at >= 20 degrees descends 0.36 units
// per unit; the terrain's whole relief is about 130 units (heights -30..100 over +-3 km), so such
// a ray meets the ground within ~400 units, far inside the grid's 4000-unit view distance. A sky
// pixel there is a hole in the grid: a wedge too narrow, or an uncovered disk under the camera.
TEST(TerrainCoverageSetup, ArgumentHolds) {
    // The relief bound the argument uses, checked on the CPU over the area the sweep flies.
    double low = 1e9, high = -1e9;
    for (double x = -1500.0; x <= 1500.0; x += 10.0)
        for (double z = -1500.0; z <= 1500.0; z += 10.0) {
            double h = groundAt(x, z);
            low = std::min(low, h);
            high = std::max(high, h);
        }
    EXPECT_LT(high - low, 140.0);
}

class TerrainCoverage : public GpuTest {};

TEST_F(TerrainCoverage, EveryRayTwentyDegreesBelowTheHorizonHitsTerrain) {
    constexpr int kWidth = 160, kHeight = 90;
    const float minDownSine = std::sin(glm::radians(20.0f));
    const glm::dvec2 places[] = {{210.0, -120.0}, {-1150.0, 1250.0}, {-400.0, -900.0}};
    const float pitches[] = {-10.0f, -35.0f, -60.0f, -75.0f, -89.9f};
    const float yaws[] = {0.0f, 70.0f, 160.0f, 250.0f, 333.0f};
    Renderer renderer(*shaders_, SceneSettings{});
    renderer.configure(kWidth, kHeight, layoutNamed("standard"));
    renderer.setPipeline(PipelineKind::Deferred);
    int checkedPixels = 0;
    std::vector<std::string> holes;
    for (glm::dvec2 place : places) {
        for (float pitch : pitches) {
            for (float yaw : yaws) {
                SceneSettings scene = sceneAt(place.x, place.y, 10.0, yaw, pitch);
                scene.water.reflections = false;
                renderer.renderFrame(scene);
                const std::vector<float> position = readTarget(renderer, Target::Position);
                const std::vector<uint8_t> stencil = readStencil(renderer);
                const glm::mat4 inverse = renderer.lastFrame().setup.data.inverseViewProjection;
                int uncovered = 0;
                float steepest = 0.0f, shallowest = -90.0f;  // elevations (degrees) of uncovered rays
                for (int y = 0; y < kHeight; ++y) {
                    for (int x = 0; x < kWidth; ++x) {
                        glm::vec4 far = inverse * glm::vec4((x + 0.5f) / kWidth * 2.0f - 1.0f,
                                                            (y + 0.5f) / kHeight * 2.0f - 1.0f, 1.0f, 1.0f);
                        glm::vec3 direction = glm::normalize(glm::vec3(far) / far.w);
                        if (direction.y > -minDownSine) continue;
                        ++checkedPixels;
                        // Nothing drawn: no terrain in the G-buffer, or neither terrain nor water in the stencil.
                        if (texel(position, kWidth, x, y).w == 0.0f || stencil[size_t(y) * kWidth + size_t(x)] == 0) {
                            ++uncovered;
                            float elevation = glm::degrees(std::asin(direction.y));
                            steepest = std::min(steepest, elevation);
                            shallowest = std::max(shallowest, elevation);
                        }
                    }
                }
                if (uncovered) {
                    char text[200];
                    std::snprintf(text, sizeof(text), "at (%.0f, %.0f) pitch %.1f yaw %.0f: %d sky pixels, rays at %.1f..%.1f deg elevation",
                                  place.x, place.y, pitch, yaw, uncovered, steepest, shallowest);
                    holes.push_back(text);
                }
            }
        }
    }
    EXPECT_GT(checkedPixels, 10000);
    std::string list;
    for (const std::string& hole : holes) list += "\n  " + hole;
    EXPECT_TRUE(holes.empty()) << holes.size() << " poses show sky below -20 degrees (holes in the terrain grid):" << list;
}

}  // namespace
}  // namespace oasis::gputest
