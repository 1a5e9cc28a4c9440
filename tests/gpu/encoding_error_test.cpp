// The encoding-error views' numbers: compact's octahedral normals within 0.01 degrees of full's
// and its positions rebuilt from D24 depth within the depth-step tolerance of gpu_test.h (the
// CompactLayout tests' bound); standard stores full's float positions, so its position error is
// exactly 0, and its half-float normals stay within 0.1 degrees; full against itself is refused.
// The probe reports the same numbers at a pixel.
#include "frame/frame_readback.h"
#include "gpu_test.h"

#include "frame/encoding_error.h"
#include "frame/pixel_probe.h"

namespace oasis::gputest {
namespace {


TEST_F(GpuTest, EncodingErrorOfEachLayoutAgainstFull) {
    const SceneSettings scene = defaultPose().scene;
    Renderer renderer(*shaders_, scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(kSmallWidth, kSmallHeight, layoutNamed("compact"));
    EXPECT_THROW(measureEncodingError(renderer, scene, layoutNamed("full")), std::invalid_argument);

    EncodingError compact = measureEncodingError(renderer, scene, renderer.targets().layout());
    EXPECT_EQ(renderer.targets().layout().name, "compact") << "left configured for the layout";
    EXPECT_GT(compact.surfaces, kSmallWidth * kSmallHeight / 2);
    ErrorSummary normals = summarizeError(compact.normalDegrees), steps = summarizeError(compact.positionSteps);
    std::printf("[encoding] compact: normal median %.2e max %.2e degrees; position median %.3f max %.3f depth steps\n",
                normals.median, normals.max, steps.median, steps.max);
    EXPECT_LT(normals.max, 0.01);
    EXPECT_GT(normals.max, 0.0) << "16-bit octahedral normals cannot be exact everywhere";
    const FrameData& frame = renderer.lastFrame().setup.data;
    int beyondTolerance = 0;
    // Every finite position error within the reconstruction tolerance at its distance.
    std::vector<float> positions = readSurfacePositions(renderer);  // compact's, the last frame drawn
    for (size_t i = 0; i < compact.positionUnits.size(); ++i) {
        if (!std::isfinite(compact.positionUnits[i])) continue;
        double distance = glm::length(glm::vec3(positions[i * 4], positions[i * 4 + 1], positions[i * 4 + 2]));
        if (compact.positionUnits[i] > reconstructionTolerance(distance, frame.depthRange.x, frame.depthRange.y))
            ++beyondTolerance;
    }
    EXPECT_EQ(beyondTolerance, 0);

    EncodingError standard = measureEncodingError(renderer, scene, layoutNamed("standard"));
    ErrorSummary standardPositions = summarizeError(standard.positionUnits);
    ErrorSummary standardNormals = summarizeError(standard.normalDegrees);
    EXPECT_EQ(standardPositions.max, 0.0) << "standard stores full's float positions";
    EXPECT_LT(standardNormals.max, 0.1);
    EXPECT_EQ(standardPositions.count, standard.surfaces);

    // The probe at a terrain pixel reports the map's numbers there.
    renderer.configure(kSmallWidth, kSmallHeight, layoutNamed("compact"));
    renderer.renderFrame(scene);
    PixelProbe probe = probePixel(renderer, 80, 80);
    addEncodingError(probe, compact);
    size_t i = size_t(kSmallHeight - 1 - 80) * kSmallWidth + 80;
    ASSERT_TRUE(probe.hasEncodingError);
    ASSERT_TRUE(std::isfinite(compact.normalDegrees[i])) << "pixel 80,80 should be terrain";
    EXPECT_EQ(probe.normalErrorDegrees, compact.normalDegrees[i]);
    EXPECT_EQ(probe.positionErrorSteps, compact.positionSteps[i]);
}

}  // namespace
}  // namespace oasis::gputest
