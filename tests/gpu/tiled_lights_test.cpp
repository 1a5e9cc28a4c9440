// The tiled light method against the stencil volumes (the reference): the same frames within the
// RGBA16F rounding of the volumes' one-light-at-a-time additions, at 0, 1, 64 and 1024 lights, with
// lights around and holding the camera, in every G-buffer layout and both depth conventions, direct
// and mirrored (Reflection); a tile reached by more lights than its list holds still gets them all;
// without compute shaders the renderer falls back to volumes and says why.
#include "frame/frame_readback.h"
#include "gpu_test.h"

namespace oasis::gputest {
namespace {

// Night over the lake's western shore, looking north-east across the water (reflections in view).
SceneSettings nightScene() {
    SceneSettings scene = sceneAtHeight(435.0, 5.0, 140.0, 30.0f, -3.0f);
    scene.hour = 21.0;
    return scene;
}

WorldPointLight lightAt(glm::dvec3 position, float radius, glm::vec3 colour, float intensity) {
    WorldPointLight light;
    light.position = position;
    light.radius = radius;
    light.colour = colour;
    light.intensity = intensity;
    return light;
}

// `count` lights over the ground in front of the camera (8 to 120 units away, 25 degrees either
// side), the first few around the camera itself (one holds it), so spheres cross the near plane,
// the frame's edges and the tiles' edges at every count.
std::vector<WorldPointLight> lightsAround(const SceneSettings& scene, int count) {
    std::vector<WorldPointLight> lights;
    const CameraPose& pose = *scene.camera;
    for (int i = 0; i < count; ++i) {
        double a = (i * 0.618034) - std::floor(i * 0.618034), b = (i * 0.7548777) - std::floor(i * 0.7548777);
        if (i < 4) {  // around and at the camera
            glm::dvec3 offset(2.0 * (a - 0.5) * i, -1.0, -1.5 * i);
            lights.push_back(lightAt(pose.position + offset, 9.0f, glm::vec3(0.9f, 0.8f, 0.6f), 4.0f));
            continue;
        }
        double yaw = glm::radians(double(pose.yawDegrees) + (a - 0.5) * 50.0), distance = 8.0 + 112.0 * b;
        double x = pose.position.x + distance * std::sin(yaw), z = pose.position.z - distance * std::cos(yaw);
        double ground = std::max(groundAt(x, z), double(scene.water.level));
        lights.push_back(lightAt(glm::dvec3(x, ground + 1.0 + 2.0 * a, z), float(6.0 + 6.0 * b),
                                 glm::vec3(1.0f, 0.5f + 0.4f * float(a), 0.2f), 30.0f));
    }
    return lights;
}

SceneSettings withLights(SceneSettings scene, std::vector<WorldPointLight> lights, LightMethod method) {
    scene.lights.list = std::move(lights);
    scene.lights.count = int(scene.lights.list->size());
    scene.lights.method = method;
    return scene;
}

// The largest difference of two RGBA16F targets relative to the brighter value (colour channels;
// a floor of 1e-3 keeps near-black texels, where fp16 steps are absolute, from dominating).
double maxRelativeDifference(const std::vector<float>& a, const std::vector<float>& b) {
    double worst = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        if (i % 4 == 3) continue;
        double scale = std::max({std::fabs(double(a[i])), std::fabs(double(b[i])), 1e-3});
        worst = std::max(worst, std::fabs(double(a[i]) - double(b[i])) / scale);
    }
    return worst;
}

// How far the total light of two targets differs, relative: a light left out shows here in full,
// the volumes' roundings only as far as they lean one way.
double totalRelativeDifference(const std::vector<float>& a, const std::vector<float>& b) {
    double sumA = 0.0, sumB = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
        if (i % 4 != 3) sumA += a[i], sumB += b[i];
    return std::fabs(sumA - sumB) / std::max(std::max(sumA, sumB), 1e-9);
}

struct Agreement {
    double radiance = 0.0, reflection = 0.0;  // max relative difference
    double radianceTotal = 0.0;               // relative difference of the summed Radiance
    ImageDifference final;
    int litPixels = 0;                        // pixels the lights brighten (the comparison means something)
};

// Renders the scene with volumes and tiled and compares Radiance, Reflection and the final image.
Agreement compareMethods(Renderer& renderer, const SceneSettings& scene, const Image* unlit) {
    Agreement result;
    SceneSettings volumes = scene, tiled = scene;
    volumes.lights.method = LightMethod::Volumes;
    tiled.lights.method = LightMethod::Tiled;
    Image reference = renderFinal(renderer, volumes, PipelineKind::Deferred);
    EXPECT_EQ(renderer.paths().lightMethod.method, LightMethod::Volumes);
    // Reflection where the frame wrote it (writtenTexels: nothing clears it outside the water).
    auto writtenReflection = [&] {
        return writtenTexels(readTarget(renderer, Target::Reflection), Target::Reflection, readStencil(renderer),
                             renderer.lastFrame().setup.reflectionsActive);
    };
    std::vector<float> radiance = readTarget(renderer, Target::Radiance), reflection = writtenReflection();
    Image image = renderFinal(renderer, tiled, PipelineKind::Deferred);
    EXPECT_EQ(renderer.paths().lightMethod.method, LightMethod::Tiled) << renderer.paths().lightMethod.reason;
    std::vector<float> tiledRadiance = readTarget(renderer, Target::Radiance);
    result.radiance = maxRelativeDifference(radiance, tiledRadiance);
    result.radianceTotal = totalRelativeDifference(radiance, tiledRadiance);
    result.reflection = maxRelativeDifference(reflection, writtenReflection());
    result.final = compareImages(reference, image);
    if (unlit)
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                for (int c = 0; c < 3; ++c)
                    if (image.pixel(x, y)[c] > unlit->pixel(x, y)[c] + 2) { ++result.litPixels; break; }
    return result;
}

// The volumes add each light to an RGBA16F target, rounding the sum each time (up to half an ulp,
// 2^-11 of it, per light); tiled sums in float and rounds once, so the texels differ by up to about
// (lights reaching the texel) x 2^-11. Measured over this file's frames (168x100): Radiance 2.9e-3
// relative at 64 lights, 1.55e-2 at 1024 (dozens of lights per texel), Reflection 5.2e-3; the
// summed Radiance 5.8e-4 and 7.3e-3 apart (the roundings lean one way, so they add up); the final
// images within 1 level of 255 (PSNR 62 dB and up).
constexpr double kMaxRelative = 2.5e-2;
constexpr double kMaxTotalRelative = 2e-2;
constexpr int kMaxFinalLevels = 2;

class TiledLights : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        if (!gl::measureCapabilities().computeAvailable(&whyNot_))
            GTEST_SKIP() << "tiled lights need compute shaders: " << whyNot_ << " (TiledLightsFallBack checks this case)";
    }
    std::string whyNot_;
};

TEST_F(TiledLights, AgreeWithVolumesInEveryLayoutAndDepthConvention) {
    const int width = 168, height = 100;  // partial tiles on the right and top edges
    SceneSettings base = nightScene();
    Renderer renderer(*shaders_, base);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    ASSERT_TRUE(renderer.paths().capabilities.compute.available);
    for (const DepthConvention& depth : depthConventions()) {
        renderer.setDepthConvention(depth);
        for (const char* layout : {"full", "standard", "compact"}) {
            renderer.configure(width, height, layoutNamed(layout));
            Image unlit = renderFinal(renderer, withLights(base, {}, LightMethod::Volumes), PipelineKind::Deferred);
            for (int count : {0, 1, 64, 1024}) {
                SCOPED_TRACE(std::string(layout) + ", depth " + depth.name + ", " + std::to_string(count) + " lights");
                Agreement a = compareMethods(renderer, withLights(base, lightsAround(base, count), LightMethod::Tiled), &unlit);
                std::printf("[tiled] %-8s %-10s %4d lights: Radiance %.2e (total %.1e), Reflection %.2e relative; "
                            "final max %d, PSNR %.1f dB; %d pixels lit\n", layout, depth.name.c_str(), count, a.radiance,
                            a.radianceTotal, a.reflection, a.final.maxAbs, a.final.psnrDb, a.litPixels);
                EXPECT_LE(a.radiance, kMaxRelative);
                EXPECT_LE(a.radianceTotal, kMaxTotalRelative);
                EXPECT_LE(a.reflection, kMaxRelative);
                EXPECT_LE(a.final.maxAbs, kMaxFinalLevels);
                if (count == 0) EXPECT_EQ(a.final.maxAbs, 0) << "no lights: both methods are the lighting pass alone";
                if (count >= 64) EXPECT_GT(a.litPixels, width * height / 10) << "the lights must show";
            }
        }
    }
}

// More lights reach one tile than its list holds (OASIS_LIGHT_TILE_MAX_LIGHTS): 1.5 times that
// many, all within half a unit of one ground point in view and each reaching 8 units, so the list
// of every tile slice holding that point overflows. Its pixels are lit from the whole list and still agree: per
// texel within the volumes' 384 roundings (384 x 2^-11 = 0.19; measured 0.105), in total within
// 0.05 (measured 0.011), where the third of the lights a truncated list would drop is 0.33.
TEST_F(TiledLights, OverflowingTileKeepsEveryLight) {
    const int width = 168, height = 100;
    SceneSettings base = nightScene();
    const CameraPose& pose = *base.camera;
    double yaw = glm::radians(double(pose.yawDegrees));
    double x = pose.position.x + 25.0 * std::sin(yaw), z = pose.position.z - 25.0 * std::cos(yaw);
    glm::dvec3 spot(x, std::max(groundAt(x, z), double(base.water.level)) + 1.0, z);
    std::vector<WorldPointLight> lights;
    const int count = OASIS_LIGHT_TILE_MAX_LIGHTS * 3 / 2;
    for (int i = 0; i < count; ++i) {
        double a = (i * 0.618034) - std::floor(i * 0.618034);
        glm::dvec3 jitter(std::cos(i * 2.4) * 0.5 * a, 0.2 * a, std::sin(i * 2.4) * 0.5 * a);
        lights.push_back(lightAt(spot + jitter, 8.0f, glm::vec3(0.6f + 0.4f * float(a), 0.5f, 0.3f), 0.2f));
    }
    Renderer renderer(*shaders_, base);
    for (const DepthConvention& depth : depthConventions()) {
        renderer.setDepthConvention(depth);
        for (const char* layout : {"standard", "compact"}) {
            SCOPED_TRACE(std::string(layout) + ", depth " + depth.name);
            renderer.configure(width, height, layoutNamed(layout));
            Image unlit = renderFinal(renderer, withLights(base, {}, LightMethod::Volumes), PipelineKind::Deferred);
            Agreement a = compareMethods(renderer, withLights(base, lights, LightMethod::Tiled), &unlit);
            std::printf("[tiled] overflow (%d lights on one spot) %s %s: Radiance %.2e (total %.1e) relative, "
                        "final max %d, PSNR %.1f dB, %d pixels lit\n", count, layout, depth.name.c_str(), a.radiance,
                        a.radianceTotal, a.final.maxAbs, a.final.psnrDb, a.litPixels);
            EXPECT_GT(a.litPixels, 200) << "the cluster must light a patch around its spot";
            EXPECT_LE(a.radiance, count * std::ldexp(1.0, -11)) << "an overflowing tile lost lights";
            EXPECT_LE(a.radianceTotal, 0.05) << "an overflowing tile lost lights";
            EXPECT_GT(a.final.psnrDb, 50.0);
        }
    }
}

// Without compute shaders (the driver's, or --force no-compute / no-ssbo as the session reports
// them) tiled falls back to volumes, says why, and draws the volumes' frame exactly.
TEST_F(GpuTest, TiledLightsFallBackToVolumesWithoutCompute) {
    const int width = 96, height = 54;
    SceneSettings base = nightScene();
    Renderer renderer(*shaders_, base);
    renderer.configure(width, height, layoutNamed("standard"));
    std::string driverReason;
    bool driverCompute = gl::measureCapabilities().computeAvailable(&driverReason);
    EXPECT_EQ(renderer.paths().capabilities.compute.available, driverCompute) << driverReason;
    if (driverCompute) {
        RendererCapabilities caps = renderer.paths().capabilities;
        caps.compute = {false, "switched off by --force no-compute"};
        caps.forcedLightMethod = LightMethod::Tiled;
        renderer.setCapabilities(caps);
    }
    SceneSettings scene = withLights(base, lightsAround(base, 64), LightMethod::Tiled);
    Image asked = renderFinal(renderer, scene, PipelineKind::Deferred);
    EXPECT_EQ(renderer.paths().lightMethod.method, LightMethod::Volumes);
    EXPECT_NE(renderer.paths().lightMethod.reason.find("tiled was asked for but"), std::string::npos) << renderer.paths().lightMethod.reason;
    EXPECT_NE(renderer.paths().lightMethod.reason.find(driverCompute ? "--force no-compute" : driverReason), std::string::npos)
        << renderer.paths().lightMethod.reason;
    scene.lights.method = LightMethod::Volumes;
    EXPECT_EQ(compareImages(asked, renderFinal(renderer, scene, PipelineKind::Deferred)).maxAbs, 0);
}

}  // namespace
}  // namespace oasis::gputest
