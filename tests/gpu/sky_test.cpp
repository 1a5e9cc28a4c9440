// The sky as drawn against its CPU twin (sky_model.cpp), the cloud deck included, by day, at dawn,
// at dusk and at night, in both pipelines; and the sun's disk: drawn where the sun is in view, as
// large as the model's disk, nowhere else, and dimmed behind a cloud that covers it.
#include "frame/frame_readback.h"
#include "gpu_test.h"
#include "render/frame_setup.h"
#include "sky_model.h"

namespace oasis::gputest {
namespace {

constexpr int kW = 320, kH = 180;

double luminance(glm::dvec3 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// Largest channel difference relative to the reference's largest channel (floor 1e-3).
double relativeError(glm::dvec3 got, glm::dvec3 want) {
    glm::dvec3 d = glm::abs(got - want);
    return std::max({d.x, d.y, d.z}) / std::max({want.x, want.y, want.z, 1e-3});
}

// One frame's Radiance and stencil, rows bottom first.
struct SkyFrame {
    FrameData frame;
    std::vector<float> radiance;
    std::vector<uint8_t> stencil;
    bool sky(int x, int y) const { return stencil[size_t(y) * kW + size_t(x)] == kStencilSky; }
    glm::dvec3 at(int x, int y) const { return glm::dvec3(rgbAt(radiance, kW, x, y)); }
};
SkyFrame render(Renderer& renderer, const SceneSettings& scene, PipelineKind kind) {
    renderer.setPipeline(kind);
    renderer.renderFrame(scene);
    return {renderer.lastFrame().setup.data, readTarget(renderer, Target::Radiance), readStencil(renderer)};
}

// A camera 5 units above the lake's level, looking along (yaw, pitch) in degrees.
SceneSettings looking(float yaw, float pitch, double hour, double time) {
    SceneSettings scene = sceneAtHeight(435.0, 5.0, 140.0, yaw, pitch);
    scene.hour = hour;
    scene.timeSeconds = time;
    return scene;
}

class Sky : public GpuTest {};

// Every direct sky pixel (stencil 0) against skyRadianceCpu along its ray, except the sun disk's
// edge and night star cells (skyIsSensitive). Radiance is RGBA16F (2^-11 relative) and the GPU
// evaluates in float: the tolerance is 2e-3 relative, as for the water's sky model (measured
// worst below). The poses look up into the deck, so that many pixels lie under clouds.
TEST_F(Sky, DrawnSkyIsTheCpuTwinCloudsIncluded) {
    Renderer renderer(*shaders_, SceneSettings{});
    renderer.configure(kW, kH, layoutNamed("compact"));
    struct Case {
        const char* name;
        SceneSettings scene;
    };
    const Case cases[] = {
        {"noon", looking(30.0f, 25.0f, 12.0, 0.0)},
        {"noon 10 min on", looking(30.0f, 25.0f, 12.0, 600.0)},
        {"dawn east", looking(90.0f, 12.0f, 6.4, 0.0)},
        {"dusk west", looking(-90.0f, 12.0f, 17.6, 0.0)},
        {"after sunset", looking(-90.0f, 12.0f, 18.5, 0.0)},
        {"night", looking(30.0f, 40.0f, 23.0, 0.0)},
    };
    for (const Case& c : cases)
        for (PipelineKind kind : {PipelineKind::Deferred, PipelineKind::Forward}) {
            SCOPED_TRACE(std::string(c.name) + " " + pipelineName(kind));
            SkyFrame s = render(renderer, c.scene, kind);
            int checked = 0, clouded = 0;
            double worst = 0.0;
            for (int y = 0; y < kH; ++y)
                for (int x = 0; x < kW; ++x) {
                    if (!s.sky(x, y)) continue;
                    glm::dvec3 ray = pixelRay(s.frame, kW, kH, x, y);
                    if (skyIsSensitive(s.frame, ray)) continue;
                    ++checked;
                    clouded += cloudCoverCpu(s.frame, ray).x > 0.3 ? 1 : 0;
                    worst = std::max(worst, relativeError(s.at(x, y), skyRadianceCpu(s.frame, ray)));
                }
            std::printf("[sky] %s %s: %d sky px (%d under clouds, cover > 0.3), worst relative error vs CPU %.2e\n",
                        c.name, pipelineName(kind), checked, clouded, worst);
            EXPECT_GT(checked, kW * kH / 4);
            EXPECT_GT(clouded, checked / 20) << "too few cloud pixels to check the clouds by";
            EXPECT_LE(worst, 2e-3) << "the drawn sky is not sky.glsl's (or its CPU twin is out of step)";
        }
}

// The sun's disk at 9:00, the camera looking straight at it: the pixels brighter than half the
// disk's radiance (4 x the sun's radiance) are the ones the CPU model's disk covers, a few edge
// pixels aside, and none lie elsewhere; when a cloud cell covers the sun (cover > 0.8 across the
// disk) none is that bright. The times with a clear and a covered sun are found on the CPU.
TEST_F(Sky, SunDiskWhereTheSunIsInViewAndBehindCloudsDimmed) {
    SceneSettings scene = looking(0.0f, 0.0f, 9.0, 0.0);
    const glm::dvec3 sun(prepareFrame(scene, kW, kH).data.sunDirection);
    scene.camera->yawDegrees = float(glm::degrees(std::atan2(sun.x, -sun.z)));
    scene.camera->pitchDegrees = float(glm::degrees(std::asin(sun.y)));
    // The cover over the disk (its centre and four points on its rim, 0.0126 rad out).
    auto coverOverDisk = [&](const FrameData& f, bool least) {
        glm::dvec3 side = glm::normalize(glm::cross(sun, glm::dvec3(0.0, 1.0, 0.0))), lift = glm::cross(side, sun);
        double result = cloudCoverCpu(f, sun).x;
        for (glm::dvec3 offset : {side, -side, lift, -lift}) {
            double cover = cloudCoverCpu(f, glm::normalize(sun + 0.0126 * offset)).x;
            result = least ? std::min(result, cover) : std::max(result, cover);
        }
        return result;
    };
    double clearTime = -1.0, coveredTime = -1.0;
    for (double t = 0.0; t < 7200.0 && (clearTime < 0.0 || coveredTime < 0.0); t += 5.0) {
        scene.timeSeconds = t;
        FrameData f = prepareFrame(scene, kW, kH).data;
        if (clearTime < 0.0 && coverOverDisk(f, false) == 0.0) clearTime = t;
        if (coveredTime < 0.0 && coverOverDisk(f, true) > 0.8) coveredTime = t;
    }
    ASSERT_GE(clearTime, 0.0) << "no clear sun in two hours";
    ASSERT_GE(coveredTime, 0.0) << "no covered sun in two hours";

    Renderer renderer(*shaders_, scene);
    renderer.configure(kW, kH, layoutNamed("compact"));
    for (PipelineKind kind : {PipelineKind::Deferred, PipelineKind::Forward})
        for (double t : {clearTime, coveredTime}) {
            const bool clear = t == clearTime;
            SCOPED_TRACE(std::string(pipelineName(kind)) + (clear ? ", clear sun" : ", covered sun") + " at t " +
                         std::to_string(t));
            scene.timeSeconds = t;
            SkyFrame s = render(renderer, scene, kind);
            const double threshold = 4.0 * luminance(glm::dvec3(s.frame.sunRadiance));
            ASSERT_GT(threshold, 0.0);
            int drawn = 0, model = 0, both = 0, far = 0;
            for (int y = 0; y < kH; ++y)
                for (int x = 0; x < kW; ++x) {
                    glm::dvec3 ray = pixelRay(s.frame, kW, kH, x, y);
                    bool inModel = luminance(skyRadianceCpu(s.frame, ray)) > threshold;
                    bool bright = s.sky(x, y) && luminance(s.at(x, y)) > threshold;
                    drawn += bright;
                    model += inModel;
                    both += bright && inModel;
                    far += bright && glm::dot(ray, sun) < std::cos(0.03);  // more than 2.4 disk radii off
                }
            std::printf("[sky] sun disk, %s, %s sun: %d bright px drawn, %d in the model's disk, %d in both, %d far "
                        "from the sun\n",
                        pipelineName(kind), clear ? "clear" : "covered", drawn, model, both, far);
            EXPECT_EQ(far, 0) << "bright pixels away from the sun";
            if (clear) {
                // About pi r^2 / pixel^2 = pi (0.0126 / (60 deg / 180 px))^2 = 15 pixels.
                EXPECT_GE(model, 5);
                EXPECT_GE(drawn, 5) << "no sun disk where the sun is in view";
                EXPECT_LE(std::abs(drawn - model), 2) << "the disk's size differs from the model's";
                EXPECT_GE(both, model - 2);
            } else {
                EXPECT_EQ(model, 0);
                EXPECT_EQ(drawn, 0) << "the sun shines through a cloud that covers it";
            }
        }
}

}  // namespace
}  // namespace oasis::gputest
