// Clouds by day (common/sky.glsl): a deck of drifting cells in the sky pixels, white by day, lit
// by the low sun's colour at dawn and dusk, dark and hiding stars at night; the same far from the
// origin and after long run times (the cloud layers are detail noise around the camera's exact
// coordinates). Where a test needs to know where the clouds are it asks the CPU twin of the sky
// (sky_model.cpp), which Sky.DrawnSkyIsTheCpuTwinCloudsIncluded holds to the drawn sky.
#include "frame/frame_readback.h"
#include "gpu_test.h"
#include "sky_model.h"

namespace oasis::gputest {
namespace {


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
        renderer.views().render("final");
        Image image = readDisplay(renderer);  // rows top first
        EXPECT_TRUE(hasContent(image));
        const std::vector<uint8_t> stencil = readStencil(renderer);  // rows bottom first
        SkyPixels s;
        for (int y = 0; y < kMediumHeight; ++y)
            for (int x = 0; x < kMediumWidth; ++x) {
                if (stencil[size_t(kMediumHeight - 1 - y) * kMediumWidth + size_t(x)] != kStencilSky) continue;
                const uint8_t* p = &image.rgba[(size_t(y) * kMediumWidth + size_t(x)) * 4];
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
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("compact"));
    for (PipelineKind kind : {PipelineKind::Deferred, PipelineKind::Forward}) {
        SCOPED_TRACE(pipelineName(kind));
        renderer.setPipeline(kind);
        Image noon, later;
        SkyPixels day = sky(renderer, lookingUp(435.0, 140.0, 12.0, 0.0), &noon);
        SkyPixels drifted = sky(renderer, lookingUp(435.0, 140.0, 12.0, 120.0), &later);
        SkyPixels night = sky(renderer, lookingUp(435.0, 140.0, 23.0, 0.0));
        ASSERT_GT(day.count, kMediumWidth * kMediumHeight / 2) << "the pose should look at the sky";
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
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("compact"));
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

// The sky pixels where the CPU twin puts cover in a band, with their Radiance (linear).
std::vector<glm::dvec3> skyRadianceWhere(Renderer& renderer, const SceneSettings& scene, PipelineKind kind,
                                         const std::function<bool(const FrameData&, glm::dvec3)>& keep) {
    renderer.setPipeline(kind);
    renderer.renderFrame(scene);
    const FrameData& f = renderer.lastFrame().setup.data;
    const std::vector<float> radiance = readTarget(renderer, Target::Radiance);
    const std::vector<uint8_t> stencil = readStencil(renderer);
    std::vector<glm::dvec3> kept;
    for (int y = 0; y < kMediumHeight; ++y)
        for (int x = 0; x < kMediumWidth; ++x)
            if (stencil[size_t(y) * kMediumWidth + size_t(x)] == kStencilSky && keep(f, pixelRay(f, kMediumWidth, kMediumHeight, x, y)))
                kept.push_back(glm::dvec3(rgbAt(radiance, kMediumWidth, x, y)));
    return kept;
}

// Thick cloud (cover > 0.8) is lit by the sun's colour: near white at noon, its red well above its
// blue with the sun a few degrees up at dawn (6:24, looking east) and dusk (17:36, looking west).
// Measured red/blue of the mean: noon about 0.8, dawn and dusk about 1.4 (sky.glsl's lighting of a
// cell: the sun's radiance, reddened when low, plus the sky's zenith and horizon colours).
TEST_F(Clouds, LitByTheLowSunsColourAtDawnAndDusk) {
    Renderer renderer(*shaders_, SceneSettings{});
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("compact"));
    auto thick = [](const FrameData& f, glm::dvec3 ray) { return cloudCoverCpu(f, ray).x > 0.8; };
    for (PipelineKind kind : {PipelineKind::Deferred, PipelineKind::Forward}) {
        SCOPED_TRACE(pipelineName(kind));
        auto redOverBlue = [&](const char* name, SceneSettings scene) {
            std::vector<glm::dvec3> cloud = skyRadianceWhere(renderer, scene, kind, thick);
            glm::dvec3 mean(0.0);
            for (glm::dvec3 c : cloud) mean += c;
            mean /= double(std::max<size_t>(cloud.size(), 1));
            std::printf("[clouds] %s %s: %zu thick-cloud px, mean (%.3f, %.3f, %.3f), red/blue %.2f\n", name,
                        pipelineName(kind), cloud.size(), mean.r, mean.g, mean.b, mean.r / mean.b);
            EXPECT_GT(cloud.size(), 200u) << name << ": too few thick-cloud pixels to judge";
            return mean.r / mean.b;
        };
        SceneSettings noon = lookingUp(435.0, 140.0, 12.0, 0.0);
        SceneSettings dawn = noon, dusk = noon;
        dawn.hour = 6.4;
        dawn.camera->yawDegrees = 90.0f;  // east, towards the rising sun
        dusk.hour = 17.6;
        dusk.camera->yawDegrees = -90.0f;  // west
        double atNoon = redOverBlue("noon", noon), atDawn = redOverBlue("dawn", dawn), atDusk = redOverBlue("dusk", dusk);
        EXPECT_LT(atNoon, 1.0) << "noon clouds should not be warm";
        EXPECT_GT(atDawn, 1.25 * atNoon) << "dawn clouds are not lit by the low sun's colour";
        EXPECT_GT(atDusk, 1.25 * atNoon) << "dusk clouds are not lit by the low sun's colour";
        EXPECT_GT(atDusk, 1.1);
    }
}

// At night the stars (star cells of the CPU twin at half brightness or more) shine where the sky
// is clear and not through thick cloud (cover > 0.9): sky.glsl weights them by (1 - cover)^2.
// Measured: clear stars' luminance about 0.3-0.6, covered ones at the cloud's own (about 0.02).
TEST_F(Clouds, StarsShineWhereClearAndNotThroughThickCloud) {
    Renderer renderer(*shaders_, SceneSettings{});
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("compact"));
    SceneSettings night = lookingUp(435.0, 140.0, 23.0, 0.0);
    night.camera->pitchDegrees = 50.0f;  // the whole frame sky, the stars at full strength
    auto star = [](const FrameData& f, glm::dvec3 ray) { return starCpu(f, ray) > 0.3; };
    for (PipelineKind kind : {PipelineKind::Deferred, PipelineKind::Forward}) {
        SCOPED_TRACE(pipelineName(kind));
        auto clearStars = skyRadianceWhere(renderer, night, kind, [&](const FrameData& f, glm::dvec3 ray) {
            return star(f, ray) && cloudCoverCpu(f, ray).x == 0.0;
        });
        auto coveredStars = skyRadianceWhere(renderer, night, kind, [&](const FrameData& f, glm::dvec3 ray) {
            return star(f, ray) && cloudCoverCpu(f, ray).x > 0.9;
        });
        auto luminance = [](glm::dvec3 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
        double clearMean = 0.0, coveredMax = 0.0;
        for (glm::dvec3 c : clearStars) clearMean += luminance(c) / double(clearStars.size());
        for (glm::dvec3 c : coveredStars) coveredMax = std::max(coveredMax, luminance(c));
        std::printf("[clouds] night %s: %zu stars in clear sky (mean luminance %.3f), %zu under thick cloud (max "
                    "%.4f)\n",
                    pipelineName(kind), clearStars.size(), clearMean, coveredStars.size(), coveredMax);
        ASSERT_GE(clearStars.size(), 5u);
        ASSERT_GE(coveredStars.size(), 5u);
        EXPECT_GT(clearMean, 0.15) << "no stars in the clear night sky";
        EXPECT_LT(coveredMax, 0.05) << "stars shine through thick cloud";
    }
}

}  // namespace
}  // namespace oasis::gputest
