// G-buffer properties per pose (deferred, layouts full and standard): unit normals, positions equal
// to those reconstructed from D24 depth, sky <=> depth 1 <=> sky flag <=> w 0 <=> stencil 0, terrain
// stencil 1, sky position = pixel ray at the far plane, and no NaN/Inf in any target; the forward
// frame's depth and stencil agree on the sky.
#include "gpu_test.h"

#include <map>

namespace oasis::gputest {
namespace {

constexpr int kWidth = 320, kHeight = 180;

// Position tolerance from D24 depth. Window depth z_w = 0.5 + 0.5 z_ndc with
// z_ndc = (f+n)/(f-n) - 2fn / ((f-n) d) for eye depth d, so one D24 step (1/(2^24-1) in z_w) moves
// the reconstructed point along its ray by  step(d) = d^2 (f-n) / (f n (2^24-1))  ~=  d^2 / (n 2^24)
// (n = 0.25, f = 6000: 0.06 at d = 500, 0.95 at d = 2000). The errors that scale the same way:
// D24 rounding (<= 1 step), z_ndc computed in float32 in the vertex shader, where z_ndc is close
// to 1 and its ulp is half a step (clip z and w and their divide: ~2 steps), and the float32
// entries of inverseViewProjection used for the reconstruction (~1 step). Allowed: 5 steps, plus
// 1e-4 relative for the float32 position/interpolation and 1 mm. Measured worst: 3.1 steps (grazing). A
// position off by one pixel sideways (3.2 units at d = 500) or by a wrong origin is far outside.
double depthStep(double eyeDistance, double nearPlane, double farPlane) {
    return eyeDistance * eyeDistance * (farPlane - nearPlane) / (farPlane * nearPlane * 16777215.0);
}
double reconstructionTolerance(double eyeDistance, double nearPlane, double farPlane) {
    return 5.0 * depthStep(eyeDistance, nearPlane, farPlane) + 1e-4 * eyeDistance + 1e-3;
}

struct FirstFailures {
    std::map<std::string, std::string> first;
    std::map<std::string, int> count;
    void note(const std::string& what, const std::string& detail) {
        if (count[what]++ == 0) first[what] = detail;
    }
};

std::string at(int x, int y) { return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + " from bottom)"; }

class GBufferProperties : public GpuTest, public ::testing::WithParamInterface<std::string> {
protected:
    void checkLayout(Renderer& renderer, const NamedPose& pose, const std::string& layout) {
        SCOPED_TRACE(pose.name + " " + layout);
        renderer.configure(kWidth, kHeight, layoutNamed(layout));
        renderer.setPipeline(PipelineKind::Deferred);
        renderer.renderFrame(pose.scene);
        const std::vector<float> albedo = renderer.readTarget(Target::Albedo);
        const std::vector<float> normal = renderer.readTarget(Target::Normal);
        const std::vector<float> position = renderer.readTarget(Target::Position);
        const std::vector<float> info = renderer.readTarget(Target::Info);
        const std::vector<float> final = renderer.readTarget(Target::Final);
        const std::vector<float> depth = renderer.readDepth();
        const std::vector<uint8_t> stencil = renderer.readStencil();

        EXPECT_EQ(countNonFinite(albedo), 0) << "albedo";
        EXPECT_EQ(countNonFinite(normal), 0) << "normal";
        EXPECT_EQ(countNonFinite(position), 0) << "position";
        EXPECT_EQ(countNonFinite(info), 0) << "info";
        EXPECT_EQ(countNonFinite(final), 0) << "final";
        EXPECT_EQ(countNonFinite(depth), 0) << "depth";

        const FrameSetup& frame = renderer.lastFrame();
        const glm::dmat4 inverse(frame.data.inverseViewProjection);
        const double nearPlane = frame.data.depthRange.x, farPlane = frame.data.depthRange.y;

        FirstFailures failures;
        int skyPixels = 0, terrainPixels = 0;
        double worstNormal = 0.0, worstRatio = 0.0, worstSteps = 0.0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                size_t i = size_t(y) * kWidth + size_t(x);
                glm::vec4 p = texel(position, kWidth, x, y);
                glm::vec4 n = texel(normal, kWidth, x, y);
                unsigned flags = infoFlags(texel(info, kWidth, x, y));
                bool depthCleared = depth[i] == 1.0f;
                bool skyFlag = (flags & kSurfaceSky) != 0u;
                bool wZero = p.w == 0.0f;
                bool stencilZero = stencil[i] == 0;
                if (!(depthCleared == skyFlag && skyFlag == wZero && wZero == stencilZero))
                    failures.note("sky markers disagree",
                                  at(x, y) + ": depth " + std::to_string(depth[i]) + ", flags " + std::to_string(flags) +
                                      ", position.w " + std::to_string(p.w) + ", stencil " + std::to_string(stencil[i]));
                if (p.w != 0.0f && p.w != 1.0f) failures.note("position.w neither 0 nor 1", at(x, y) + ": " + std::to_string(p.w));
                glm::dvec2 ndcXY((x + 0.5) / kWidth * 2.0 - 1.0, (y + 0.5) / kHeight * 2.0 - 1.0);
                if (wZero) {
                    ++skyPixels;
                    if (flags != (kSurfaceSky | kSurfaceUnlit))
                        failures.note("sky flags not SKY|UNLIT", at(x, y) + ": " + std::to_string(flags));
                    // The sky stores its view direction scaled to the far plane.
                    glm::dvec4 far = inverse * glm::dvec4(ndcXY, 1.0, 1.0);
                    glm::dvec3 ray = glm::normalize(glm::dvec3(far) / far.w);
                    glm::dvec3 stored(p);
                    if (std::fabs(glm::length(stored) - farPlane) > 1e-3 * farPlane ||
                        glm::length(glm::normalize(stored) - ray) > 1e-3)
                        failures.note("sky position is not the pixel's ray at the far plane",
                                      at(x, y) + ": |p| " + std::to_string(glm::length(stored)));
                    continue;
                }
                if (p.w != 1.0f) continue;
                ++terrainPixels;
                if (stencil[i] != 1) failures.note("terrain stencil != 1", at(x, y) + ": " + std::to_string(stencil[i]));
                if (flags != 0u) failures.note("terrain flags != 0", at(x, y) + ": " + std::to_string(flags));

                double length = glm::length(glm::dvec3(n));
                worstNormal = std::max(worstNormal, std::fabs(length - 1.0));
                if (std::fabs(length - 1.0) > 1e-3) failures.note("normal not unit", at(x, y) + ": |n| = " + std::to_string(length));
                if (n.y <= 0.0f) failures.note("terrain normal faces down", at(x, y) + ": n.y = " + std::to_string(n.y));

                glm::dvec4 ndc(ndcXY, double(depth[i]) * 2.0 - 1.0, 1.0);
                glm::dvec4 world = inverse * ndc;
                glm::dvec3 reconstructed = glm::dvec3(world) / world.w;
                glm::dvec3 stored(p);
                double distance = glm::length(stored);
                double error = glm::length(reconstructed - stored);
                double tolerance = reconstructionTolerance(distance, nearPlane, farPlane);
                worstRatio = std::max(worstRatio, error / tolerance);
                if (distance > 50.0) worstSteps = std::max(worstSteps, error / depthStep(distance, nearPlane, farPlane));
                if (error > tolerance)
                    failures.note("position != depth reconstruction",
                                  at(x, y) + ": stored distance " + std::to_string(distance) + ", error " +
                                      std::to_string(error) + " > tolerance " + std::to_string(tolerance));
            }
        }
        std::printf("[gbuffer] pose=%s layout=%s sky=%d terrain=%d worst |n|-1=%.2e worst position error "
                    "%.2f D24 steps (beyond 50 units), %.3f of tolerance\n",
                    pose.name.c_str(), layout.c_str(), skyPixels, terrainPixels, worstNormal, worstSteps, worstRatio);
        for (const auto& [what, count] : failures.count)
            ADD_FAILURE() << what << " at " << count << " pixels; first " << failures.first[what];
        EXPECT_EQ(skyPixels + terrainPixels, kWidth * kHeight) << "pixels that are neither sky nor terrain";
        if (pose.expectSky) EXPECT_GT(skyPixels, 0) << "no sky in view";
        else EXPECT_EQ(skyPixels, 0) << "sky visible where only terrain should be (a hole in the terrain?)";
        if (pose.expectTerrain) EXPECT_GT(terrainPixels, 0) << "no terrain in view";
        else EXPECT_EQ(terrainPixels, 0) << "terrain visible where only sky should be";
    }

    // The forward frame writes the same depth and stencil: sky (depth 1) exactly where stencil is 0.
    void checkForward(Renderer& renderer, const NamedPose& pose) {
        SCOPED_TRACE(pose.name + " forward");
        renderer.setPipeline(PipelineKind::Forward);
        renderer.renderFrame(pose.scene);
        const std::vector<float> depth = renderer.readDepth();
        const std::vector<uint8_t> stencil = renderer.readStencil();
        EXPECT_EQ(countNonFinite(depth), 0);
        EXPECT_EQ(countNonFinite(renderer.readTarget(Target::Final)), 0);
        int mismatches = 0, firstMismatch = -1;
        for (size_t i = 0; i < depth.size(); ++i) {
            bool sky = depth[i] == 1.0f;
            bool ok = sky ? stencil[i] == 0 : stencil[i] == 1;
            if (!ok && mismatches++ == 0) firstMismatch = int(i);
        }
        EXPECT_EQ(mismatches, 0) << "depth 1 <=> stencil 0 (else stencil 1) fails; first at index " << firstMismatch;
    }
};

TEST_P(GBufferProperties, DeferredFullAndStandard) {
    NamedPose pose = poseNamed(GetParam());
    Renderer renderer(*shaders_, pose.scene);
    checkLayout(renderer, pose, "full");
    checkLayout(renderer, pose, "standard");
    checkForward(renderer, pose);
}

INSTANTIATE_TEST_SUITE_P(Poses, GBufferProperties,
                         ::testing::Values("default", "grazing", "down", "up", "sunset", "night"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace oasis::gputest
