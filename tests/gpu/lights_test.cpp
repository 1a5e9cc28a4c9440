// Point lights: the three light paths give bit-identical frames in each pipeline (0, 1, 64 and
// the UBO capacity + 1 lights); forward and deferred agree with 64 lights; a volume that crosses
// the near plane or holds the camera lights without holes and leaves the stencil as it was (these
// two under each depth convention: the volumes' stencil marking compares depth both ways); edits
// to the lights take effect the next frame in every path; the light-volumes view counts lights.
#include "frame/frame_readback.h"
#include "gpu_test.h"

#include <cstring>

#include "passes/light_volume_pass.h"

namespace oasis::gputest {
namespace {

constexpr LightsPath kPaths[] = {LightsPath::Ssbo, LightsPath::SsboCount, LightsPath::Ubo};

// Night over the lake's western shore, looking north-east across the water to the hills.
SceneSettings nightScene() {
    SceneSettings scene = sceneAtHeight(435.0, 5.0, 140.0, 30.0f, -3.0f);
    scene.hour = 21.0;
    return scene;
}

// `count` lights spread over the ground (or the water) in front of the camera, 8 to 120 units
// away and 25 degrees either side, each 1 to 3 units above it; `shift` moves them all.
std::vector<WorldPointLight> lightsInView(const SceneSettings& scene, int count, glm::dvec3 shift = glm::dvec3(0.0)) {
    std::vector<WorldPointLight> lights;
    const CameraPose& pose = *scene.camera;
    for (int i = 0; i < count; ++i) {
        double a = (i * 0.618034) - std::floor(i * 0.618034), b = (i * 0.7548777) - std::floor(i * 0.7548777);
        double yaw = glm::radians(double(pose.yawDegrees) + (a - 0.5) * 50.0), distance = 8.0 + 112.0 * b;
        double x = pose.position.x + distance * std::sin(yaw), z = pose.position.z - distance * std::cos(yaw);
        double ground = std::max(groundAt(x, z), double(scene.water.level));
        WorldPointLight light;
        light.position = glm::dvec3(x, ground + 1.0 + 2.0 * a, z) + shift;
        light.radius = float(6.0 + 6.0 * b);
        light.colour = glm::vec3(1.0f, 0.5f + 0.4f * float(a), 0.2f);
        light.intensity = 30.0f;
        lights.push_back(light);
    }
    return lights;
}

SceneSettings withLights(SceneSettings scene, std::vector<WorldPointLight> lights, std::optional<LightsPath> path) {
    scene.lights.list = std::move(lights);
    scene.lights.count = int(scene.lights.list->size());
    scene.lights.path = path;
    return scene;
}

// Pixels where `lit` is brighter than `unlit` by more than `by` in some channel.
int brighterPixels(const Image& lit, const Image& unlit, int by = 2) {
    int count = 0;
    for (int y = 0; y < lit.height; ++y)
        for (int x = 0; x < lit.width; ++x)
            for (int c = 0; c < 3; ++c)
                if (lit.pixel(x, y)[c] > unlit.pixel(x, y)[c] + by) { ++count; break; }
    return count;
}

bool sameFloats(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

class Lights : public GpuTest {};

TEST_F(Lights, ThreePathsAreBitIdenticalInEachPipeline) {
    const int width = 128, height = 72;
    SceneSettings base = nightScene();
    Renderer renderer(*shaders_, base);
    auto atlas = attachPlantAtlas(*shaders_, renderer);  // plants are lit by the point lights too
    renderer.configure(width, height, layoutNamed("standard"));
    ASSERT_TRUE(renderer.paths().capabilities.ssbo.available) << "this test needs SSBOs (GL 4.3) to compare the paths";
    const int capacity = renderer.paths().uboLights.capacity;
    std::printf("[lights] ubo capacity %d lights per block, %d blocks\n", capacity, renderer.paths().uboLights.blocks);
    ASSERT_GE(capacity, 8);
    for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
        Image unlit;
        for (int count : {0, 1, 64, capacity + 1}) {
            SCOPED_TRACE(std::string(pipelineName(kind)) + ", " + std::to_string(count) + " lights");
            std::vector<float> firstRadiance;
            Image first;
            for (LightsPath path : kPaths) {
                SCOPED_TRACE(lightsPathName(path));
                SceneSettings scene = withLights(base, lightsInView(base, count), path);
                Image image = renderFinal(renderer, scene, kind);
                EXPECT_EQ(renderer.paths().lights.path, path);
                EXPECT_EQ(renderer.paths().lightsDrawn, count);
                EXPECT_EQ(renderer.paths().lightsDropped, 0);
                std::vector<float> radiance = readTarget(renderer, Target::Radiance);
                if (first.width == 0) {
                    first = image;
                    firstRadiance = radiance;
                    dumpImage(std::string("lights-paths-") + pipelineName(kind) + "-" + std::to_string(count), image);
                } else {
                    EXPECT_EQ(compareImages(first, image).maxAbs, 0) << "the final image depends on the light path";
                    EXPECT_TRUE(sameFloats(firstRadiance, radiance)) << "Radiance depends on the light path";
                }
            }
            if (count == 0) {
                unlit = first;
            } else {
                // The lights must show, or the comparison proves nothing.
                int lit = brighterPixels(first, unlit);
                std::printf("[lights] %s %d lights: %d of %d pixels lit\n", pipelineName(kind), count, lit,
                            width * height);
                EXPECT_GT(lit, count == 1 ? 10 : width * height / 20);
            }
        }
    }
}

TEST_F(Lights, ForwardAndDeferredAgreeWith64Lights) {
    SceneSettings scene = withLights(nightScene(), lightsInView(nightScene(), 64), std::nullopt);
    Renderer renderer(*shaders_, scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);  // plants are lit by the point lights too
    for (const DepthConvention& depth : depthConventions())
    for (auto [layout, minPsnr] : {std::pair{"full", 55.0}, std::pair{"standard", 45.0}, std::pair{"compact", 45.0}}) {
        SCOPED_TRACE(std::string(layout) + ", depth " + depth.name);
        renderer.setDepthConvention(depth);
        renderer.configure(320, 180, layoutNamed(layout));
        Image forward = renderFinal(renderer, scene, PipelineKind::Forward);
        Image deferred = renderFinal(renderer, scene, PipelineKind::Deferred);
        Image unlit = renderFinal(renderer, nightScene(), PipelineKind::Deferred);
        dumpImage(std::string("lights-64-forward-") + layout, forward);
        dumpImage(std::string("lights-64-deferred-") + layout, deferred);
        ImageDifference difference = compareImages(forward, deferred);
        std::printf("[lights] 64 lights, %s, %s depth: forward vs deferred PSNR %.2f dB, max %d\n", layout,
                    renderer.paths().depth->name.c_str(), difference.psnrDb, difference.maxAbs);
        EXPECT_GE(difference.psnrDb, minPsnr);
        EXPECT_GT(brighterPixels(deferred, unlit), 320 * 180 / 10) << "the lights barely show";
    }
}

// A light around the camera, and one whose sphere is cut by the near plane just ahead of it: every
// pixel forward lights, deferred lights too (no stencil holes), and the stencil keeps no mark.
TEST_F(Lights, VolumesThatHoldTheCameraOrCrossTheNearPlaneHaveNoHoles) {
    const int width = 320, height = 180;
    SceneSettings base = sceneAt(300.0, -60.0, 2.0, 45.0f, -35.0f);  // looking down at nearby ground
    base.hour = 21.0;
    const CameraPose& pose = *base.camera;
    glm::dvec3 forwardDir = glm::dvec3(std::sin(glm::radians(double(pose.yawDegrees))) * std::cos(glm::radians(-35.0)),
                                       std::sin(glm::radians(-35.0)),
                                       -std::cos(glm::radians(double(pose.yawDegrees))) * std::cos(glm::radians(-35.0)));
    const float nearPlane = base.projection.nearPlane;
    struct Case {
        std::string name;
        WorldPointLight light;
    };
    std::vector<Case> cases;
    WorldPointLight around;
    around.position = pose.position + glm::dvec3(0.0, 0.5, 0.0);
    around.radius = 8.0f;
    around.colour = glm::vec3(1.0f, 0.8f, 0.5f);
    around.intensity = 40.0f;
    cases.push_back({"camera inside", around});
    WorldPointLight cut = around;
    cut.radius = 3.0f;
    cut.position = pose.position + forwardDir * double(cut.radius + 0.5f * nearPlane);  // front cap behind the near plane
    cases.push_back({"near plane crossing", cut});

    Renderer renderer(*shaders_, base);
    renderer.configure(width, height, layoutNamed("full"));
    for (const DepthConvention& depth : depthConventions())
    for (const Case& c : cases) {
        renderer.setDepthConvention(depth);
        for (LightsPath path : kPaths) {
            SCOPED_TRACE(c.name + ", " + lightsPathName(path) + ", depth " + renderer.paths().depth->name);
            SceneSettings scene = withLights(base, {c.light}, path);
            SceneSettings dark = withLights(base, {}, path);
            Image forward = renderFinal(renderer, scene, PipelineKind::Forward);
            Image forwardUnlit = renderFinal(renderer, dark, PipelineKind::Forward);
            Image deferredUnlit = renderFinal(renderer, dark, PipelineKind::Deferred);
            std::vector<uint8_t> stencilUnlit = readStencil(renderer);
            Image deferred = renderFinal(renderer, scene, PipelineKind::Deferred);
            dumpImage("lights-near-" + std::to_string(&c - cases.data()) + "-deferred", deferred);
            int litForward = brighterPixels(forward, forwardUnlit);
            int holes = 0;
            for (int y = 0; y < height; ++y)
                for (int x = 0; x < width; ++x) {
                    bool forwardLit = false, deferredLit = false;
                    for (int ch = 0; ch < 3; ++ch) {
                        forwardLit |= forward.pixel(x, y)[ch] > forwardUnlit.pixel(x, y)[ch] + 4;
                        deferredLit |= deferred.pixel(x, y)[ch] > deferredUnlit.pixel(x, y)[ch];
                    }
                    holes += forwardLit && !deferredLit;
                }
            std::printf("[lights] %s, %s depth: %d pixels lit forward, %d holes in deferred\n", c.name.c_str(),
                        renderer.paths().depth->name.c_str(), litForward, holes);
            EXPECT_GT(litForward, width * height / 20) << "the light should light much of the view";
            EXPECT_EQ(holes, 0) << "deferred misses pixels the forward pipeline lights";
            EXPECT_GE(compareImages(forward, deferred).psnrDb, 45.0);
            EXPECT_TRUE(readStencil(renderer) == stencilUnlit) << "the light volumes left marks in the stencil";
        }
    }
}

// Edits between frames: the count and the positions change, and the next frame in the same
// renderer equals a first frame of a fresh renderer with the new lights, in every path.
TEST_F(Lights, EditsTakeEffectTheNextFrameInEveryPath) {
    const int width = 128, height = 72;
    SceneSettings base = nightScene();
    Renderer renderer(*shaders_, base);
    renderer.configure(width, height, layoutNamed("standard"));
    for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
        for (LightsPath path : kPaths) {
            SCOPED_TRACE(std::string(pipelineName(kind)) + ", " + lightsPathName(path));
            SceneSettings before = withLights(base, lightsInView(base, 24), path);
            SceneSettings moved = withLights(base, lightsInView(base, 24, glm::dvec3(6.0, 0.0, -4.0)), path);
            SceneSettings more = withLights(base, lightsInView(base, 48, glm::dvec3(6.0, 0.0, -4.0)), path);
            Image first = renderFinal(renderer, before, kind);
            Image afterMove = renderFinal(renderer, moved, kind);
            Image afterCount = renderFinal(renderer, more, kind);
            Renderer fresh(*shaders_, moved);
            fresh.configure(width, height, layoutNamed("standard"));
            EXPECT_GT(compareImages(first, afterMove).maxAbs, 8) << "moving the lights changed nothing";
            EXPECT_EQ(compareImages(afterMove, renderFinal(fresh, moved, kind)).maxAbs, 0);
            EXPECT_GT(compareImages(afterMove, afterCount).maxAbs, 8) << "adding lights changed nothing";
            EXPECT_EQ(compareImages(afterCount, renderFinal(fresh, more, kind)).maxAbs, 0);
        }
    }
}

// The light-volumes view: each surface pixel's colour class follows the number of lights whose
// sphere holds it, counted on the CPU from the G-buffer positions (dark grey 0, blue 1, green 2).
TEST_F(Lights, LightVolumesViewCountsTheLightsAtEachPixel) {
    const int width = 160, height = 90;
    SceneSettings base = nightScene();
    base.water.reflections = false;  // the G-buffer holds the direct scene everywhere
    std::vector<WorldPointLight> lights = lightsInView(base, 6);
    SceneSettings scene = withLights(base, lights, std::nullopt);
    Renderer renderer(*shaders_, scene);
    renderer.configure(width, height, layoutNamed("full"));
    Image view = renderView(renderer, scene, PipelineKind::Deferred, "light-volumes");
    dumpImage("lights-volumes-view", view);
    std::vector<float> position = readTarget(renderer, Target::Position);
    std::vector<float> info = readTarget(renderer, Target::Info);
    const glm::dvec3 eye = renderer.lastFrame().setup.view.pose.position;
    int counted[3] = {0, 0, 0}, wrong = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (infoFlags(texel(info, width, x, y)) & kSurfaceSky) continue;
            glm::dvec3 p = glm::dvec3(glm::vec3(texel(position, width, x, y)));
            int touching = 0;
            for (const WorldPointLight& light : lights)
                touching += glm::distance(light.position - eye, p) < double(light.radius);
            glm::ivec3 c = displayPixel(view, x, y);
            bool ok = touching == 0   ? (c.x == c.y && c.y == c.z)
                      : touching == 1 ? (c.z > c.x + 40 && c.z > c.y + 40)
                      : touching == 2 ? (c.y > c.x + 40 && c.y > c.z + 40)
                                      : true;
            if (touching < 3) ++counted[touching];
            // Within a hair of a sphere the GPU's float and the CPU's double may round apart.
            wrong += !ok;
        }
    std::printf("[lights] view: %d pixels with no light, %d with one, %d with two; %d wrong\n", counted[0], counted[1],
                counted[2], wrong);
    EXPECT_GT(counted[0], 100);
    EXPECT_GT(counted[1], 100);
    EXPECT_LE(wrong, (counted[0] + counted[1] + counted[2]) / 200);
}

}  // namespace
}  // namespace oasis::gputest
