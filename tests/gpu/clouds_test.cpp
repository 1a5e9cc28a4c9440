// Clouds by day (common/sky.glsl): a deck of drifting cells in the sky pixels, white by day, lit
// by the low sun's colour at dusk, dark and hiding stars at night; the same far from the origin and
// after long run times (the cloud layers are detail noise around the camera's exact coordinates).
#include "gpu_test.h"

namespace oasis::gputest {
namespace {

constexpr int kWidth = 320, kHeight = 180;

// What the sky pixels (stencil 0) of a frame hold.
struct SkyPixels {
    long count = 0;
    long bright = 0;      // cloud-white: every channel above 0.6 and nearly grey (max - min < 0.2)
    long nonFinite = 0;
    double meanLuminance = 0.0;
};

class Clouds : public GpuTest {
protected:
    SkyPixels sky(Renderer& renderer, const SceneSettings& scene, Image* out = nullptr) {
        renderer.renderFrame(scene);
        renderer.renderView("final");
        Image image = renderer.readDisplay();  // rows top first
        EXPECT_TRUE(hasContent(image));
        const std::vector<uint8_t> stencil = renderer.readStencil();  // rows bottom first
        SkyPixels s;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                if (stencil[size_t(kHeight - 1 - y) * kWidth + size_t(x)] != kStencilSky) continue;
                const uint8_t* p = &image.rgba[(size_t(y) * kWidth + size_t(x)) * 4];
                double r = p[0] / 255.0, g = p[1] / 255.0, b = p[2] / 255.0;
                ++s.count;
                s.meanLuminance += 0.2126 * r + 0.7152 * g + 0.0722 * b;
                if (std::min({r, g, b}) > 0.6 && std::max({r, g, b}) - std::min({r, g, b}) < 0.2) ++s.bright;
            }
        if (s.count) s.meanLuminance /= double(s.count);
        if (out) *out = image;
        return s;
    }
};

SceneSettings lookingUp(double x, double z, double hour, double time) {
    SceneSettings scene = sceneAtHeight(x, 5.0, z, 30.0f, 25.0f);
    scene.hour = hour;
    scene.timeSeconds = time;
    return scene;
}

TEST_F(Clouds, DayHasDriftingCloudsNightHidesStarsBehindDarkOnes) {
    Renderer renderer(*shaders_, SceneSettings{});
    renderer.configure(kWidth, kHeight, layoutNamed("compact"));
    for (PipelineKind kind : {PipelineKind::Deferred, PipelineKind::Forward}) {
        SCOPED_TRACE(pipelineName(kind));
        renderer.setPipeline(kind);
        Image noon, later;
        SkyPixels day = sky(renderer, lookingUp(435.0, 140.0, 12.0, 0.0), &noon);
        SkyPixels drifted = sky(renderer, lookingUp(435.0, 140.0, 12.0, 120.0), &later);
        SkyPixels night = sky(renderer, lookingUp(435.0, 140.0, 23.0, 0.0));
        ASSERT_GT(day.count, kWidth * kHeight / 2) << "the pose should look at the sky";
        double cloudShare = double(day.bright) / double(day.count);
        std::printf("[clouds] %s: day %.1f%% of %ld sky pixels cloud-white (mean luminance %.3f), night %.1f%% "
                    "(mean %.3f)\n",
                    pipelineName(kind), 100.0 * cloudShare, day.count, day.meanLuminance,
                    100.0 * double(night.bright) / double(night.count), night.meanLuminance);
        EXPECT_GT(cloudShare, 0.05) << "hardly a cloud by day";
        EXPECT_LT(cloudShare, 0.8) << "an overcast sky: the deck's cover is too high";
        // At night the only white pixels are stars (a few in a thousand cells), the clouds dark.
        EXPECT_LT(double(night.bright) / double(night.count), 0.005) << "white clouds at night";
        EXPECT_LT(night.meanLuminance, 0.5 * day.meanLuminance);
        // Two minutes later the cells have moved: many sky pixels change.
        long changed = 0;
        for (size_t i = 0; i < noon.rgba.size(); i += 4)
            if (std::abs(int(noon.rgba[i]) - int(later.rgba[i])) > 8) ++changed;
        EXPECT_GT(changed, day.count / 20) << "the clouds did not drift in 120 s";
        EXPECT_EQ(drifted.count, day.count) << "the drift changed what is sky";
    }
}

// 1e5 units out and a million seconds on, the deck looks as it does at the origin (no banding,
// no frozen or NaN sky): its cover stays in the same band.
TEST_F(Clouds, FarAwayAndLongAfterTheDeckLooksTheSame) {
    Renderer renderer(*shaders_, SceneSettings{});
    renderer.configure(kWidth, kHeight, layoutNamed("compact"));
    renderer.setPipeline(PipelineKind::Deferred);
    for (auto [x, z, time] : {std::tuple{435.0, 140.0, 0.0}, std::tuple{1e5, 1e5, 0.0}, std::tuple{435.0, 140.0, 1e6},
                              std::tuple{-3e6, 2e6, 4e6}}) {
        SCOPED_TRACE("camera " + std::to_string(x) + ", " + std::to_string(z) + " at " + std::to_string(time) + " s");
        SceneSettings scene = lookingUp(x, z, 12.0, time);
        scene.camera->position.y = groundAt(x, z) + 30.0;  // above the ground wherever that is
        SkyPixels s = sky(renderer, scene);
        ASSERT_GT(s.count, 0);
        double share = double(s.bright) / double(s.count);
        std::printf("[clouds] camera (%.0f, %.0f), t %.0f s: %.1f%% cloud-white\n", x, z, time, 100.0 * share);
        EXPECT_GT(share, 0.02);
        EXPECT_LT(share, 0.85);
    }
}

}  // namespace
}  // namespace oasis::gputest
