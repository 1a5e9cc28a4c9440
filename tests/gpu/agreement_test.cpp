// Forward and deferred agree: PSNR of the final images (full layout >= 55 dB, standard and compact >= 45 dB)
// for the default frame at 1280x720 (it shows the lake and plants), five hard poses, three water
// poses and a meadow at 320x180, all with vegetation, and every image has content.
#include "frame/frame_readback.h"
#include "gpu_test.h"

namespace oasis::gputest {
namespace {

struct LayoutThreshold {
    const char* layout;
    double minPsnrDb;
};
constexpr LayoutThreshold kThresholds[] = {{"full", 55.0}, {"standard", 45.0}, {"compact", 45.0}};

class Agreement : public GpuTest {
protected:
    void checkAgreement(const NamedPose& pose, int width, int height) {
        Renderer renderer(*shaders_, pose.scene);
        auto atlas = attachPlantAtlas(*shaders_, renderer);
        Image firstForward;
        for (const LayoutThreshold& threshold : kThresholds) {
            SCOPED_TRACE(pose.name + " " + threshold.layout + " " + std::to_string(width) + "x" + std::to_string(height));
            renderer.configure(width, height, layoutNamed(threshold.layout));
            Image forward = renderFinal(renderer, pose.scene, PipelineKind::Forward);
            Image deferred = renderFinal(renderer, pose.scene, PipelineKind::Deferred);
            std::vector<float> albedo = readTarget(renderer, Target::Albedo);  // the deferred frame's
            std::vector<uint8_t> stencil = readStencil(renderer);
            double waterShare = double(std::count(stencil.begin(), stencil.end(), kStencilWater)) / double(stencil.size());
            double plantShare = double(std::count(stencil.begin(), stencil.end(), kStencilPlant)) / double(stencil.size());
            dumpImage("agreement-" + pose.name + "-" + threshold.layout + "-forward", forward);
            dumpImage("agreement-" + pose.name + "-" + threshold.layout + "-deferred", deferred);

            // The forward pipeline never touches the G-buffer: its image cannot depend on the layout.
            if (firstForward.width == 0) {
                firstForward = forward;
            } else {
                EXPECT_EQ(compareImages(firstForward, forward).maxAbs, 0) << "forward image changed with the layout";
            }

            ImageDifference difference = compareImages(forward, deferred);
            std::printf("[psnr] pose=%s layout=%s size=%dx%d psnr=%.2f dB rmse=%.4f maxAbs=%d water=%.1f%% "
                        "plants=%.1f%%\n", pose.name.c_str(), threshold.layout, width, height, difference.psnrDb,
                        difference.rmse, difference.maxAbs, 100.0 * waterShare, 100.0 * plantShare);
            if (pose.name == "default" || pose.name == "meadow") {
                EXPECT_GT(plantShare, pose.name == "meadow" ? 0.05 : 0.01) << "a vegetation frame with few plants";
            }
            if (pose.name == "default" || pose.name.rfind("lake", 0) == 0) {
                EXPECT_GT(waterShare, 0.1) << "a water frame with little water in view";
            }
            RecordProperty("psnr_" + pose.name + "_" + threshold.layout, std::to_string(difference.psnrDb));
            EXPECT_GE(difference.psnrDb, threshold.minPsnrDb)
                << "forward and deferred disagree (rmse " << difference.rmse << ", max " << difference.maxAbs << ")";

            for (const Image* image : {&forward, &deferred}) {
                const char* which = image == &forward ? "forward" : "deferred";
                std::printf("[content] pose=%s layout=%s %s: %s\n", pose.name.c_str(), threshold.layout, which,
                            describe(rgbStats(*image, wholeImage(*image))).c_str());
                if (pose.smoothSky) {
                    // A view of nothing but sky may be one smooth gradient: it must be lit and finite.
                    RgbStats stats = rgbStats(*image, wholeImage(*image));
                    EXPECT_GT(stats.maxMean(), 20.0) << which << " sky view is black: " << describe(stats);
                    EXPECT_EQ(countNonFiniteWritten(albedo, Target::Albedo, stencil, false), 0)
                        << "non-finite surface colour in the G-buffer";
                } else {
                    EXPECT_TRUE(hasContent(*image)) << which;
                }
            }
        }
    }
};

TEST_F(Agreement, DefaultFrameAt1280x720) { checkAgreement(defaultPose(), 1280, 720); }

class AgreementPose : public Agreement, public ::testing::WithParamInterface<std::string> {};

TEST_P(AgreementPose, BothLayoutsAt320x180) { checkAgreement(poseNamed(GetParam()), 320, 180); }

INSTANTIATE_TEST_SUITE_P(HardPoses, AgreementPose,
                         ::testing::Values("grazing", "down", "up", "sunset", "night"),
                         [](const auto& info) { return info.param; });

// Water frames over the lake: a still mirror, a grazing view 0.5 above rippled water, and the low
// sun glinting on it (the default frame above shows the lake too).
INSTANTIATE_TEST_SUITE_P(WaterPoses, AgreementPose, ::testing::Values("lakeMirror", "lakeGrazing", "lakeSunset"),
                         [](const auto& info) { return info.param; });

// Among the plants, near and far, with their reflections.
INSTANTIATE_TEST_SUITE_P(VegetationPoses, AgreementPose, ::testing::Values("meadow"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace oasis::gputest
