// Sun shadows (passes/shadow_pass.h, common/shadows.glsl) against an independent CPU answer: for
// each terrain pixel, march its ray towards the sun over the CPU terrain height field. Where the
// ray stays clear above the ground the GPU must say lit (no acne); where ground blocks it farther
// than the stated bound the GPU must say shadowed (no peter-panning beyond it). With the sun low
// (long grazing shadows), near the horizon, 1e5 units out; night runs no shadow pass; the eye
// at the water plane; forward and deferred agree with shadows on (agreement_test.cpp too).
#include "frame/frame_readback.h"
#include "gpu_test.h"
#include "shader_dir_copy.h"

#include "scene/sky.h"

namespace oasis::gputest {
namespace {

// The peter-panning bound: an occluder farther than this along the sun ray from the receiver (in
// texels of the receiver's cascade: 1 unit in cascade 0 of the default quality) must shadow it.
// The receiver's offsets (common/shadows.glsl) are 2.5 texels. (At 2 texels the frames below pass
// as well: the CPU comparison's margins, not the shadows, limit what this can resolve.)
constexpr double kPeterPanningTexels = 4.0;
// How far above (clear) or below (blocked) the ground the CPU ray must pass to count: half a unit,
// plus 1% of the distance marched, plus 3% of the sample's distance from the camera, because the
// drawn terrain (which casts and receives) is a polar grid whose rings are 6.7% of their radius
// apart (150 rings to 4000 units): its chords cut small ridges the height field has.
double marginAt(double t, double fromCamera) { return 0.5 + 0.01 * t + 0.03 * fromCamera; }

enum class Truth { Clear, Blocked, Unsure };

// The ray from the surface point towards the sun over the CPU height field, to `reach` units.
Truth marchToSun(const TerrainShape& shape, glm::dvec3 camera, glm::dvec3 point, glm::dvec3 toSun, double blockedFrom,
                 double reach) {
    bool clear = true;
    for (double t = 0.25; t < reach; t += std::max(0.25, t * 0.01)) {
        glm::dvec3 q = point + toSun * t;
        double above = q.y - terrainHeight(shape, glm::dvec2(q.x, q.z)).x;
        double margin = marginAt(t, glm::length(glm::dvec2(q.x - camera.x, q.z - camera.z)));
        if (t >= blockedFrom && above < -margin) return Truth::Blocked;
        if (t >= 5.0 && above < margin) clear = false;
    }
    return clear ? Truth::Clear : Truth::Unsure;
}

struct ShadowCheck {
    int clear = 0, acne = 0, blocked = 0, missed = 0;
};

class Shadows : public GpuTest {
protected:
    // Renders `scene` deferred (full layout, no plants: the CPU knows only the terrain), reads the
    // shadow view's values and the surfaces, and compares every sun-facing terrain pixel.
    // At least `minClear` sunlit and `minBlocked` shadowed pixels must be judged, so neither
    // check can pass on a frame that has none.
    ShadowCheck checkAgainstCpu(const std::string& name, SceneSettings scene, int minClear, int minBlocked,
                                int width = 320, int height = 180) {
        scene.vegetation.enabled = false;
        Renderer renderer(*shaders_, scene);
        renderer.configure(width, height, layoutNamed("full"));
        renderer.setPipeline(PipelineKind::Deferred);
        renderer.renderFrame(scene);
        const FrameSetup& frame = renderer.lastFrame().setup;
        EXPECT_TRUE(frame.shadowsActive) << name;
        renderer.views().render("shadow");
        dumpImage("shadows-" + name, readDisplay(renderer));
        renderer.views().render("final");
        Image final = readDisplay(renderer);
        dumpImage("shadows-" + name + "-final", final);
        EXPECT_TRUE(hasContent(final)) << name;
        std::vector<float> values = renderer.views().readValues("shadow");
        std::vector<float> positions = readSurfacePositions(renderer);
        glm::dvec3 camera = frame.view.pose.position;
        glm::dvec3 toSun = glm::normalize(glm::dvec3(frame.sky.sunDirection));
        ShadowCheck check;
        int cascadesSeen[OASIS_SHADOW_MAX_CASCADES] = {};
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                size_t i = (size_t(y) * size_t(width) + size_t(x)) * 4;
                if (positions[i + 3] == 0.0f) continue;  // sky
                float lit = values[i], facing = values[i + 2];
                int cascade = int(std::lround(values[i + 1]));
                if (cascade < 0 || facing < 0.15f) continue;  // beyond the maps, or a face the sun barely lights
                ++cascadesSeen[cascade];
                glm::dvec3 point = camera + glm::dvec3(positions[i], positions[i + 1], positions[i + 2]);
                double bound = kPeterPanningTexels * double(frame.shadowCascades.texel[cascade]);
                Truth truth = marchToSun(scene.terrain, camera, point, toSun, bound, 3000.0);
                if (truth == Truth::Clear) {
                    ++check.clear;
                    if (lit < 0.5f) ++check.acne;
                } else if (truth == Truth::Blocked) {
                    ++check.blocked;
                    if (lit > 0.5f) ++check.missed;
                }
            }
        std::printf("[shadows] %s: sun elevation %.2f deg; clear %d (acne %d), blocked %d (missed %d); pixels per "
                    "cascade %d %d %d %d\n", name.c_str(), glm::degrees(std::asin(toSun.y)), check.clear, check.acne,
                    check.blocked, check.missed, cascadesSeen[0], cascadesSeen[1], cascadesSeen[2], cascadesSeen[3]);
        EXPECT_GE(check.clear, minClear) << name << ": too few sunlit pixels to judge acne";
        EXPECT_GE(check.blocked, minBlocked) << name << ": too few shadowed pixels to judge the shadows";
        EXPECT_LE(check.acne, check.clear / 100) << name << ": lit ground shadowed (acne)";
        EXPECT_LE(check.missed, check.blocked / 100 + 2) << name << ": shadows missing (peter-panning)";
        return check;
    }

    // A pose `above` the ground at (x, z) looking towards the sun's azimuth at `hour` (so the
    // occluders between the ground in view and the sun lie in the drawn terrain wedge).
    static SceneSettings facingTheSun(double x, double z, double above, double hour, float pitch) {
        glm::vec3 sun = skyAtHour(hour).sunDirection;
        float yaw = glm::degrees(std::atan2(sun.x, -sun.z));
        SceneSettings scene = sceneAt(x, z, above, yaw, pitch);
        scene.hour = hour;
        return scene;
    }
};

TEST_F(Shadows, LowSunLongShadowsMatchTheTerrain) {
    checkAgainstCpu("low-sun", facingTheSun(210.0, -120.0, 40.0, 7.0, -12.0f), 1000, 500);
}

// The lookup's four taps (tentFilteredShadow in common/shadows.glsl) against the 3x3 taps of the
// 2x2 comparison they stand for: the shadow view's sunlit fraction of a frame with long shadows
// (many pixels in a penumbra), drawn with the shaders as they are and with the nine-tap loop put
// back in a copy of shadows.glsl. The weights are the same; only the filter's own rounding may
// differ. Four taps at whole-texel offsets (the placement dropped) miss by up to 0.22 here.
TEST_F(Shadows, FourTapsGiveTheNineTheyReplace) {
    const int width = 320, height = 180;
    SceneSettings scene = facingTheSun(210.0, -120.0, 40.0, 7.0, -12.0f);
    auto shadowValues = [&](ShaderLibrary& library) {
        Renderer renderer(library, scene);
        renderer.configure(width, height, layoutNamed("full"));
        renderer.setPipeline(PipelineKind::Deferred);
        renderer.renderFrame(scene);
        renderer.views().render("shadow");
        return renderer.views().readValues("shadow");
    };
    std::vector<float> four = shadowValues(*shaders_);

    ShaderDirCopy copy(shaderDir_);
    const auto file = copy.root / "common" / "shadows.glsl";
    std::string text = readText(file);
    const std::string call = "result.lit = tentFilteredShadow(coord, c, mapSize);";
    ASSERT_NE(text.find(call), std::string::npos) << "shadows.glsl no longer calls tentFilteredShadow so";
    text.replace(text.find(call), call.size(),
                 "float sum = 0.0;\n"
                 "        for (int y = -1; y <= 1; ++y)\n"
                 "            for (int x = -1; x <= 1; ++x)\n"
                 "                sum += texture(shadowMap, vec4(coord.xy + vec2(float(x), float(y)) / mapSize, "
                 "float(c), coord.z));\n"
                 "        result.lit = sum / 9.0;");
    writeText(file, text);
    ShaderLibrary nineTaps(copy.root.string(), glslDialectForCurrentContext());
    std::vector<float> nine = shadowValues(nineTaps);

    ASSERT_EQ(four.size(), nine.size());
    int penumbra = 0, compared = 0;
    double worst = 0.0, sum = 0.0;
    for (size_t i = 0; i < four.size(); i += 4) {
        if (int(std::lround(nine[i + 1])) < 0) continue;  // beyond the maps (or sky): no lookup
        ++compared;
        if (nine[i] > 0.02f && nine[i] < 0.98f) ++penumbra;
        double difference = std::fabs(double(four[i]) - double(nine[i]));
        worst = std::max(worst, difference);
        sum += difference;
        EXPECT_EQ(four[i + 1], nine[i + 1]) << "the cascade differs at pixel " << i / 4;
    }
    std::printf("[shadows] four taps vs nine: %d pixels looked up, %d in a penumbra; worst %.2e, mean %.2e\n",
                compared, penumbra, worst, sum / std::max(compared, 1));
    EXPECT_GE(compared, width * height / 3);
    EXPECT_GE(penumbra, 300) << "too few penumbra pixels: the filters' difference would not show";
    EXPECT_LE(worst, 2.0 / 255.0);
    // A GPU places each bilinear tap with 8-bit sub-texel weights, so the placed taps stand for the
    // nine only to about 1/512 each (H100: worst 3.0e-3, mean 1.75e-4; llvmpipe: 2.2e-5, 1.4e-6).
    EXPECT_LE(sum / std::max(compared, 1), cpuRasteriser() ? 1e-4 : 5e-4);
}

TEST_F(Shadows, SunAtTheHorizonGrazing) {
    // Less than 2 degrees up: the hills shadow all the ground in view, so only the shadows are judged
    // here (acne needs sunlit ground: the low-sun frame).
    checkAgainstCpu("horizon", facingTheSun(210.0, -120.0, 40.0, 6.15, -12.0f), 0, 1000);
}

TEST_F(Shadows, FarCameraSameGuarantees) {
    checkAgainstCpu("far", facingTheSun(1e5, 1e5, 40.0, 7.0, -12.0f), 200, 500);
}

TEST_F(Shadows, NightRunsNoShadowPass) {
    SceneSettings scene;
    scene.hour = 21.0;
    Renderer renderer(*shaders_, scene);
    renderer.configure(160, 90, layoutNamed("compact"));
    for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
        renderer.setPipeline(kind);
        std::vector<std::string> ran;
        renderer.renderFrame(scene, FrameRequest::observed([&](const Pass& pass) { ran.push_back(pass.name()); }));
        EXPECT_EQ(std::count(ran.begin(), ran.end(), "ShadowPass"), 0) << pipelineName(kind);
        std::vector<float> values = renderer.views().readValues("shadow");
        for (size_t i = 0; i < values.size(); i += 4) {
            ASSERT_EQ(values[i], 1.0f) << "shadowed at night";
            ASSERT_EQ(values[i + 1], -1.0f) << "a cascade answered at night";
        }
    }
    // By day the same frame runs it (so the check above can fail).
    scene.hour = 10.0;
    std::vector<std::string> ran;
    renderer.renderFrame(scene, FrameRequest::observed([&](const Pass& pass) { ran.push_back(pass.name()); }));
    EXPECT_EQ(std::count(ran.begin(), ran.end(), "ShadowPass"), 1);
}

// Shadows off changes nothing but the shadowed pixels: the frame with shadows off is the frame of
// the shadow view's lit fraction 1 everywhere, and on differs (the default frame has shadows).
TEST_F(Shadows, OffIsLitEverywhereAndOnDarkens) {
    SceneSettings scene = poseNamed("meadow").scene;
    Renderer renderer(*shaders_, scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(320, 180, layoutNamed("compact"));
    scene.hour = 8.0;
    Image on = renderFinal(renderer, scene, PipelineKind::Deferred);
    std::vector<float> onValues = renderer.views().readValues("shadow");
    scene.shadows.enabled = false;
    Image off = renderFinal(renderer, scene, PipelineKind::Deferred);
    std::vector<float> offValues = renderer.views().readValues("shadow");
    int shadowed = 0;
    for (size_t i = 0; i < onValues.size(); i += 4) {
        ASSERT_EQ(offValues[i], 1.0f);
        if (onValues[i] < 0.5f) ++shadowed;
    }
    EXPECT_GT(shadowed, 320 * 180 / 100) << "the meadow at 8:00 should have shadows (plants and hills)";
    double darker = 0.0;
    for (size_t i = 0; i < on.rgba.size(); i += 4) darker += double(off.rgba[i + 1]) - double(on.rgba[i + 1]);
    EXPECT_GT(darker, 0.0) << "shadows should darken the frame";
    dumpImage("shadows-meadow-on", on);
    dumpImage("shadows-meadow-off", off);
}

// The plants cast shadows (alpha-tested as drawn): with them, terrain pixels darken in the shadow
// view; without, the same terrain pixels are lit by the same maps' terrain alone.
TEST_F(Shadows, PlantsCastShadowsOnTheGround) {
    SceneSettings scene = sceneAtHeight(400.0, 22.0, 175.0, 60.0f, -40.0f);
    scene.hour = 9.0;
    Renderer renderer(*shaders_, scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(320, 180, layoutNamed("full"));
    renderer.setPipeline(PipelineKind::Deferred);
    renderer.renderFrame(scene);
    std::vector<float> with = renderer.views().readValues("shadow");
    std::vector<uint8_t> stencil = readStencil(renderer);
    EXPECT_GT(renderer.lastFrame().vegetation.stats().plantsDrawn, 100u);
    SceneSettings bare = scene;
    bare.vegetation.enabled = false;
    renderer.renderFrame(bare);
    std::vector<float> without = renderer.views().readValues("shadow");
    int darkened = 0, lightened = 0;
    for (size_t p = 0; p < stencil.size(); ++p) {
        if (stencil[p] != kStencilTerrain) continue;
        darkened += with[p * 4] < without[p * 4] - 0.25f;
        lightened += with[p * 4] > without[p * 4] + 0.01f;
    }
    std::printf("[shadows] plants: %d terrain pixels darkened by plant shadows, %d lightened\n", darkened, lightened);
    EXPECT_GT(darkened, 100) << "the plants cast no shadow";
    EXPECT_EQ(lightened, 0) << "plants can only take light away";
}

// The eye exactly at the water plane, low sun: both pipelines draw it, agree, and the reflection's
// surfaces are shadowed at their real positions (the mirrored scene's shadow view answers).
TEST_F(Shadows, EyeAtTheWaterPlane) {
    SceneSettings scene = sceneAtHeight(470.0, 0.0, 150.0, 30.0f, 2.0f);
    scene.hour = 16.5;
    Renderer renderer(*shaders_, scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(320, 180, layoutNamed("compact"));
    Image forward = renderFinal(renderer, scene, PipelineKind::Forward);
    Image deferred = renderFinal(renderer, scene, PipelineKind::Deferred);
    EXPECT_TRUE(hasContent(forward));
    ImageDifference difference = compareImages(forward, deferred);
    std::printf("[shadows] eye at the water plane: forward vs deferred %.2f dB\n", difference.psnrDb);
    EXPECT_GE(difference.psnrDb, 45.0);
    std::vector<float> values = renderer.views().readValues("shadow");
    EXPECT_EQ(countNonFinite(values), 0);
}

}  // namespace
}  // namespace oasis::gputest
