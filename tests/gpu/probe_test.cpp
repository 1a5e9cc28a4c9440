// The pixel probe against a CPU read-back of the same frame: at sky, terrain, plant, water
// (direct and mirrored) and lit-by-lights pixels, in both pipelines and every G-buffer layout, the
// probe's values (decoded on the GPU by shaders/probe.frag through common/gbuffer.glsl) equal the
// targets read back and decoded on the CPU (GBufferLayout::storedNormal / storedFlags,
// readSurfacePositions, readDepth, readStencil), and its stored bytes are the targets' own.
#include "frame/frame_readback.h"
#include "gpu_test.h"

#include "frame/pixel_probe.h"

namespace oasis::gputest {
namespace {


// Still water in front of a shore with plants, at 21:00 with lights over the land and the lake:
// every kind of pixel the probe explains is in this frame.
SceneSettings probeScene() {
    SceneSettings scene = sceneAtHeight(435.0, 4.0, 140.0, 30.0f, -3.0f);
    scene.hour = 21.0;
    scene.water.rippleStrength = 0.6f;
    std::vector<WorldPointLight> lights;
    const CameraPose& pose = *scene.camera;
    for (int i = 0; i < 24; ++i) {
        double a = (i * 0.618034) - std::floor(i * 0.618034), b = (i * 0.7548777) - std::floor(i * 0.7548777);
        double yaw = glm::radians(double(pose.yawDegrees) + (a - 0.5) * 50.0), distance = 8.0 + 112.0 * b;
        double x = pose.position.x + distance * std::sin(yaw), z = pose.position.z - distance * std::cos(yaw);
        WorldPointLight light;
        light.position = glm::dvec3(x, std::max(groundAt(x, z), 0.0) + 1.0 + 2.0 * a, z);
        light.radius = float(8.0 + 8.0 * b);
        light.colour = glm::vec3(1.0f, 0.6f, 0.3f);
        light.intensity = 30.0f;
        lights.push_back(light);
    }
    scene.lights.list = lights;
    scene.lights.count = int(lights.size());
    return scene;
}

enum class PixelKind { Sky, Terrain, Plant, WaterDirect, WaterMirrored, Lit, Count };
const char* kindName(PixelKind kind) {
    static const char* names[] = {"sky", "terrain", "plant", "water (direct scene)", "water (mirrored scene)", "lit"};
    return names[int(kind)];
}

struct CpuFrame {
    std::vector<float> albedo, normal, info, positions, radiance, reflection, final, depth;
    std::vector<uint8_t> stencil;
};

// The lights whose sphere holds a camera-relative point, and whether any sphere's edge is too
// close to it to decide in float.
int lightsReaching(const FrameSetup& frame, glm::dvec3 point, bool& ambiguous) {
    int count = 0;
    for (const PointLight& light : frame.lights) {
        double d = glm::distance(glm::dvec3(light.positionRadius), point), r = light.positionRadius.w;
        if (std::fabs(d - r) < 1e-3 * r) ambiguous = true;
        if (d < r) ++count;
    }
    return count;
}

class Probe : public GpuTest, public ::testing::WithParamInterface<std::tuple<PipelineKind, std::string>> {};

TEST_P(Probe, AgreesWithTheCpuReadBackAtEveryKindOfPixel) {
    auto [pipeline, layoutName] = GetParam();
    const SceneSettings scene = probeScene();
    Renderer renderer(*shaders_, scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    const GBufferLayout& layout = layoutNamed(layoutName);
    renderer.configure(kSmallWidth, kSmallHeight, layout);
    renderer.setPipeline(pipeline);
    // Both water scenes are checked: the mirrored one in deferred, the direct one (the lakebed) in forward.
    renderer.views().setWaterScene(pipeline == PipelineKind::Deferred ? WaterScene::Mirrored : WaterScene::Direct);
    renderer.renderFrame(scene);
    renderer.views().ensureGBuffer();  // the views' fill of the water scene, as the probe and the views read it

    CpuFrame cpu{readTarget(renderer, Target::Albedo), readTarget(renderer, Target::Normal),
                 readTarget(renderer, Target::Info), readSurfacePositions(renderer),
                 readTarget(renderer, Target::Radiance), readTarget(renderer, Target::Reflection),
                 readTarget(renderer, Target::Final), readDepth(renderer), readStencil(renderer)};
    const FrameSetup& frame = renderer.lastFrame().setup;
    // Nothing drawn (gbufferSkyAt): by depth at the far plane in the compact layout, whose colour
    // targets are not cleared there, by Info's SKY flag in the others. The probe shows the texels
    // no pass wrote (those, and Reflection outside the water) as the clear used to leave them.
    auto flagsAt = [&](int x, int y) {
        if (layout.positionFromDepth() ? cpu.depth[size_t(y) * kSmallWidth + size_t(x)] >= 1.0f
                                       : (layout.storedFlags(texel(cpu.info, kSmallWidth, x, y)) & kSurfaceSky) != 0u)
            return unsigned(kSurfaceSky);
        return layout.storedFlags(texel(cpu.info, kSmallWidth, x, y));
    };

    // Up to four pixels of each kind, spread over the frame (GL rows, bottom 0).
    std::vector<std::pair<PixelKind, glm::ivec2>> pixels;
    int found[int(PixelKind::Count)] = {};
    auto take = [&](PixelKind kind, int x, int y) {
        if (found[int(kind)]++ % 7 == 0 && found[int(kind)] <= 22) pixels.push_back({kind, {x, y}});
    };
    for (int y = 1; y < kSmallHeight - 1; y += 3)
        for (int x = 1; x < kSmallWidth - 1; x += 3) {
            size_t i = size_t(y) * kSmallWidth + size_t(x);
            unsigned flags = flagsAt(x, y);
            int stencil = cpu.stencil[i];
            if (stencil == kStencilNothing) take(PixelKind::Sky, x, y);
            if (stencil == kStencilTerrain) take(PixelKind::Terrain, x, y);
            if (stencil == kStencilVegetation) take(PixelKind::Plant, x, y);
            if (stencil == kStencilWater)
                take((flags & kSurfaceReflected) ? PixelKind::WaterMirrored : PixelKind::WaterDirect, x, y);
            if (!(flags & kSurfaceSky)) {
                glm::dvec3 p = glm::dvec3(texel(cpu.positions, kSmallWidth, x, y));
                if (flags & kSurfaceReflected) p.y = 2.0 * (double(scene.water.level) - frame.view.pose.position.y) - p.y;
                bool ambiguous = false;
                if (lightsReaching(frame, p, ambiguous) > 0 && !ambiguous) take(PixelKind::Lit, x, y);
            }
        }
    for (PixelKind kind : {PixelKind::Sky, PixelKind::Terrain, PixelKind::Plant, PixelKind::Lit})
        EXPECT_GT(found[int(kind)], 0) << "no " << kindName(kind) << " pixel in the probe scene";
    // The water pixels hold the scene asked for above.
    PixelKind water = pipeline == PipelineKind::Deferred ? PixelKind::WaterMirrored : PixelKind::WaterDirect;
    EXPECT_GT(found[int(water)], 0) << "no " << kindName(water) << " pixel";

    int checked = 0;
    for (const auto& [kind, pixel] : pixels) {
        int x = pixel.x, yFromBottom = pixel.y;
        PixelProbe probe = probePixel(renderer, x, kSmallHeight - 1 - yFromBottom);
        size_t i = size_t(yFromBottom) * kSmallWidth + size_t(x);
        std::string where = std::string(kindName(kind)) + " pixel " + std::to_string(x) + "," +
                            std::to_string(kSmallHeight - 1 - yFromBottom);
        glm::vec4 info = texel(cpu.info, kSmallWidth, x, yFromBottom);
        unsigned flags = flagsAt(x, yFromBottom);
        const bool reflectionWritten = frame.reflectionsActive && cpu.stencil[i] == kStencilWater;
        EXPECT_EQ(probe.flags, flags) << where;
        EXPECT_EQ(probe.sky, (flags & kSurfaceSky) != 0) << where;
        EXPECT_EQ(probe.stencil, int(cpu.stencil[i])) << where;
        EXPECT_NEAR(probe.depth, double(cpu.depth[i]), 1e-7) << where;  // glReadPixels' float of the same bits
        EXPECT_EQ(probe.radiance, texel(cpu.radiance, kSmallWidth, x, yFromBottom)) << where;
        EXPECT_EQ(probe.reflection, reflectionWritten ? texel(cpu.reflection, kSmallWidth, x, yFromBottom) : glm::vec4(0.0f))
            << where;
        EXPECT_EQ(probe.final, glm::ivec4(glm::round(texel(cpu.final, kSmallWidth, x, yFromBottom) * 255.0f))) << where;
        EXPECT_EQ(probe.waterScene.empty(), cpu.stencil[i] != kStencilWater) << where;
        // The stored albedo bytes are the target's (every layout's albedo is RGBA8 except full's floats).
        const StoredTexel& albedoTexel = probe.stored.front();
        ASSERT_EQ(albedoTexel.target, "albedo");
        glm::vec4 albedo = (flags & kSurfaceSky) ? glm::vec4(0.0f) : texel(cpu.albedo, kSmallWidth, x, yFromBottom);
        for (int c = 0; c < 4; ++c)
            EXPECT_EQ(albedoTexel.values[size_t(c)],
                      albedoTexel.format == "RGBA8" ? double(std::lround(albedo[c] * 255.0f)) : double(albedo[c]))
                << where << " albedo channel " << c;
        if (flags & kSurfaceSky) continue;
        EXPECT_NEAR(glm::distance(probe.albedo, glm::vec3(albedo)), 0.0f, 1e-6f) << where;
        glm::vec3 normal = layout.storedNormal(texel(cpu.normal, kSmallWidth, x, yFromBottom));
        EXPECT_NEAR(glm::distance(probe.normal, normal), 0.0f, 2e-5f) << where;
        glm::vec3 position = glm::vec3(texel(cpu.positions, kSmallWidth, x, yFromBottom));
        EXPECT_NEAR(glm::distance(probe.relativePosition, position), 0.0f, 1e-5f * (1.0f + glm::length(position)))
            << where;
        EXPECT_EQ(probe.specularPower, std::round(info.r * 255.0f)) << where;
        glm::dvec3 real = glm::dvec3(position);
        if (flags & kSurfaceReflected) real.y = 2.0 * (double(scene.water.level) - frame.view.pose.position.y) - real.y;
        EXPECT_NEAR(glm::distance(probe.worldPosition, frame.view.pose.position + real), 0.0, 1e-4 * (1.0 + glm::length(real)))
            << where;
        bool ambiguous = false;
        int reaching = lightsReaching(frame, real, ambiguous);
        if (!ambiguous) EXPECT_EQ(probe.lightsReaching, reaching) << where;
        EXPECT_EQ(probe.lightsInList, int(frame.lights.size())) << where;
        if (kind == PixelKind::Lit) EXPECT_GT(probe.lightsReaching, 0) << where;
        ++checked;
    }
    EXPECT_GE(checked, 12);
}

std::string probeParamName(const ::testing::TestParamInfo<std::tuple<PipelineKind, std::string>>& info) {
    return std::string(pipelineName(std::get<0>(info.param))) + "_" + std::get<1>(info.param);
}

INSTANTIATE_TEST_SUITE_P(EveryPipelineAndLayout, Probe,
                         ::testing::Combine(::testing::Values(PipelineKind::Forward, PipelineKind::Deferred),
                                            ::testing::Values("full", "standard", "compact")),
                         probeParamName);

// The probe says how the reflection it reads was drawn: at which resolution and into targets of
// which size (a reduced one reaches Reflection through a bilinear upsample), or that no mirrored
// scene was drawn (reflections off; the camera under the water).
TEST_F(GpuTest, ProbeSaysHowTheReflectionWasDrawn) {
    struct Case {
        int divisor;
        bool reflections;
        double cameraHeight;
        const char* name;  // "" for none drawn
        int width, height;
    };
    const Case cases[] = {{1, true, 4.0, "full", 160, 90},   {2, true, 4.0, "half", 80, 45},
                          {4, true, 4.0, "quarter", 40, 23}, {2, false, 4.0, "", 0, 0},
                          {2, true, -3.0, "", 0, 0}};
    for (const Case& c : cases) {
        SceneSettings scene = sceneAtHeight(435.0, c.cameraHeight, 140.0, 30.0f, -3.0f);
        scene.water.reflections = c.reflections;
        scene.water.reflectionDivisor = c.divisor;
        Renderer renderer(*shaders_, scene);
        renderer.configure(kSmallWidth, kSmallHeight, layoutNamed("compact"));
        renderer.renderFrame(scene);
        PixelProbe probe = probePixel(renderer, kSmallWidth / 2, kSmallHeight - 5);
        SCOPED_TRACE(std::string("divisor ") + std::to_string(c.divisor) + (c.reflections ? "" : ", reflections off") +
                     ", camera at " + std::to_string(c.cameraHeight));
        EXPECT_EQ(probe.reflectionResolution, c.name);
        EXPECT_EQ(probe.reflectionWidth, c.width);
        EXPECT_EQ(probe.reflectionHeight, c.height);
        const std::string text = probeText(probe), json = probeJson(probe);
        if (*c.name == '\0') {
            EXPECT_NE(text.find("no mirrored scene drawn this frame"), std::string::npos) << text;
            EXPECT_NE(json.find("\"reflection_resolution\": null"), std::string::npos) << json;
        } else {
            std::string size = std::to_string(c.width) + "x" + std::to_string(c.height);
            bool reduced = c.divisor > 1;
            EXPECT_EQ(text.find("drawn at " + std::string(c.name) + " resolution" + (reduced ? ", " + size : "")) !=
                          std::string::npos, true) << text;
            EXPECT_EQ(text.find("upsampled bilinearly") != std::string::npos, reduced) << text;
            EXPECT_NE(json.find("\"reflection_resolution\": {\"name\": \"" + std::string(c.name) + "\", \"width\": " +
                                std::to_string(c.width) + ", \"height\": " + std::to_string(c.height) + "}"),
                      std::string::npos) << json;
        }
    }
}

// Outside the frame the probe refuses; the CLI turns that into exit 2 before any GL work.
TEST_F(GpuTest, ProbeOutsideTheFrameThrows) {
    SceneSettings scene;
    Renderer renderer(*shaders_, scene);
    renderer.configure(32, 18, layoutNamed("compact"));
    renderer.renderFrame(scene);
    EXPECT_THROW(probePixel(renderer, 32, 0), std::out_of_range);
    EXPECT_THROW(probePixel(renderer, 0, -1), std::out_of_range);
    EXPECT_NO_THROW(probePixel(renderer, 31, 17));
}

}  // namespace
}  // namespace oasis::gputest
