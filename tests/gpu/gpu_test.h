// Shared fixture of the GPU tests: the process-wide headless context (created by main.cpp), GL
// error capture, the poses the suite renders, and image/buffer helpers (statistics, finiteness).
#pragma once
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "common/shared_constants.glsl"
#include "context/gl_context.h"
#include "frame/frame_readback.h"
#include "frame/renderer.h"
#include "render/image.h"
#include "render/plant_atlas.h"
#include "render/shader_library.h"
#include "render/texture_units.h"
#include "scene/terrain.h"

namespace oasis::gputest {

// The frame sizes the tests draw at, one name for each size (the test files compile in unity
// batches, where a file-local kWidth would be defined twice).
inline constexpr int kTinyWidth = 96, kTinyHeight = 54;
inline constexpr int kSmallWidth = 160, kSmallHeight = 90;
inline constexpr int kMediumWidth = 320, kMediumHeight = 180;

// The one context of the process and what went wrong making it (main.cpp owns both).
struct GpuState {
    std::unique_ptr<HeadlessContext> context;
    std::string error;        // why there is no context
    std::string skipReason;   // the driver set-up asked for ($OASIS_GPU_SETUP) is not available here
    ContextInfo info;
    std::vector<std::string> glErrors;  // GL_DEBUG_TYPE_ERROR messages (API source) since the last clear
};
GpuState& gpuState();

// Every GPU test derives from this: it fails without a context (skips, with the reason, only when
// the driver set-up named by $OASIS_GPU_SETUP is not available on this machine), gives each test a
// shader library on the real shader directory, and fails a test that left a GL error behind.
class GpuTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!gpuState().skipReason.empty()) GTEST_SKIP() << gpuState().skipReason;
        if (!gpuState().context) GTEST_FAIL() << "no headless OpenGL context: " << gpuState().error;
        std::string searched;
        shaderDir_ = findShaderDirectory(&searched);
        ASSERT_FALSE(shaderDir_.empty()) << "shader directory not found (searched " << searched << ")";
        shaders_ = std::make_unique<ShaderLibrary>(shaderDir_, glslDialectForCurrentContext());
        while (glGetError() != GL_NO_ERROR) {}
        gpuState().glErrors.clear();
    }
    void TearDown() override {
        if (!gpuState().context) return;
        GLenum error = glGetError();
        EXPECT_EQ(error, GLenum(GL_NO_ERROR)) << "GL error left behind: " << gl::errorString(error);
        for (const std::string& message : gpuState().glErrors) ADD_FAILURE() << "GL debug error: " << message;
        gpuState().glErrors.clear();
    }

    std::string shaderDir_;
    std::unique_ptr<ShaderLibrary> shaders_;
};

// Whether the context rasterises on the CPU through Mesa's gallivm (llvmpipe, softpipe, zink
// over lavapipe): there float arithmetic is IEEE single precision without contraction, texture
// weights are exact and conversions round to nearest, so tests bound rounding at its least. A
// GPU is allowed its hardware's precision (fused multiply-adds, 8-bit filter weights, its depth
// interpolation): those tests take a second, looser bound, measured on an NVIDIA H100 and named
// where it is used.
inline bool cpuRasteriser() {
    const std::string& renderer = gpuState().info.renderer;
    return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
}

// ---------------------------------------------------------------------------------------------
// Poses. Ground heights come from the CPU terrain so cameras sit a known height above it.

struct NamedPose {
    std::string name;
    SceneSettings scene;
    bool expectSky = true;      // some sky pixels must be visible
    bool expectTerrain = true;  // some terrain pixels must be visible
    bool smoothSky = false;     // the whole frame is a smooth sky gradient (content check relaxed)
};

inline double groundAt(double x, double z) { return terrainHeight(TerrainShape{}, glm::dvec2(x, z)).x; }

inline SceneSettings sceneAt(double x, double z, double aboveGround, float yaw, float pitch) {
    SceneSettings scene;
    scene.camera = CameraPose{glm::dvec3(x, groundAt(x, z) + aboveGround, z), yaw, pitch};
    return scene;
}

// The default frame: time 0, the default flight, 10:00.
inline NamedPose defaultPose() { return {"default", SceneSettings{}, true, true, false}; }

// The five hard poses of the agreement and buffer tests.
inline std::vector<NamedPose> hardPoses() {
    std::vector<NamedPose> poses;
    // Grazing: 1.5 units above a flat valley floor, looking almost level (2 degrees down) along it.
    // Since the water came the valley is a lake (floor -9.2, level 0): the camera is 7.7 units under
    // water and sees the sky only through the surface (no stencil-0 pixels, SKY flags in the water).
    poses.push_back({"grazing", sceneAt(-1150.0, 1250.0, 1.5, 30.0f, -2.0f), true, true, false});
    // Straight down from 20 units: only terrain in view.
    poses.push_back({"down", sceneAt(210.0, -120.0, 20.0, 90.0f, -89.9f), false, true, false});
    // Straight up: only sky (the frustum spans 60 to 90 degrees of elevation).
    poses.push_back({"up", sceneAt(210.0, -120.0, 20.0, 90.0f, 89.9f), true, false, true});
    // Sun on the horizon at 18:00 in the west (-X): look west, slightly down.
    {
        SceneSettings scene = sceneAt(210.0, -120.0, 30.0, -90.0f, -3.0f);
        scene.hour = 18.0;
        poses.push_back({"sunset", scene, true, true, false});
    }
    // Sun below the horizon at 21:00 (night sky, stars): the default flight.
    {
        SceneSettings scene;
        scene.hour = 21.0;
        poses.push_back({"night", scene, true, true, false});
    }
    return poses;
}

// Water poses over the lake east of the default flight's start (bed about -10 at (490, 100), level 0).
inline SceneSettings sceneAtHeight(double x, double y, double z, float yaw, float pitch) {
    SceneSettings scene;
    scene.camera = CameraPose{glm::dvec3(x, y, z), yaw, pitch};
    return scene;
}
inline std::vector<NamedPose> waterPoses() {
    std::vector<NamedPose> poses;
    // A still, clear mirror: from the western shore (5 units up) across the lake to the hills.
    {
        SceneSettings scene = sceneAtHeight(435.0, 5.0, 140.0, 30.0f, -3.0f);
        scene.water.rippleStrength = 0.0f;
        scene.water.absorption = 0.0f;
        poses.push_back({"lakeMirror", scene, true, true, false});
    }
    // Grazing: 0.5 units above the (rippled, default) water, 1 degree down, across the lake.
    poses.push_back({"lakeGrazing", sceneAtHeight(470.0, 0.5, 150.0, 30.0f, -1.0f), true, true, false});
    // Late afternoon from the eastern shore, looking west into the low sun: its glint on the water.
    {
        SceneSettings scene = sceneAtHeight(580.0, 12.0, 120.0, -80.0f, -4.0f);
        scene.hour = 17.5;
        poses.push_back({"lakeSunset", scene, true, true, false});
    }
    return poses;
}

// Among the plants: 6 units above the lake's western shore, looking north-east over a meadow
// (plants near and far, and their reflections in the water on the right).
inline std::vector<NamedPose> vegetationPoses() {
    return {{"meadow", sceneAtHeight(420.0, 6.0, 160.0, 40.0f, -4.0f), true, true, false}};
}

inline std::vector<NamedPose> allPoses() {
    std::vector<NamedPose> poses{defaultPose()};
    for (NamedPose& pose : hardPoses()) poses.push_back(pose);
    for (NamedPose& pose : waterPoses()) poses.push_back(pose);
    for (NamedPose& pose : vegetationPoses()) poses.push_back(pose);
    return poses;
}

inline NamedPose poseNamed(const std::string& name) {
    for (const NamedPose& pose : allPoses())
        if (pose.name == name) return pose;
    throw std::invalid_argument("no pose " + name);
}

inline const GBufferLayout& layoutNamed(const std::string& name) {
    const GBufferLayout* layout = findGBufferLayout(name);
    if (!layout) throw std::invalid_argument("no G-buffer layout " + name);
    return *layout;
}

// ---------------------------------------------------------------------------------------------
// Rendering shortcuts.

inline Image renderFinal(Renderer& renderer, const SceneSettings& scene, PipelineKind kind) {
    renderer.setPipeline(kind);
    renderer.renderFrame(scene);
    renderer.views().render("final");
    return readDisplay(renderer);
}

inline Image renderView(Renderer& renderer, const SceneSettings& scene, PipelineKind kind, const std::string& view) {
    renderer.setPipeline(kind);
    renderer.renderFrame(scene);
    renderer.views().render(view);
    return readDisplay(renderer);
}

// The plant atlas the app would build on this context, attached to a renderer made in a test (so
// its frames draw vegetation). The caller keeps it alive as long as the renderer draws.
inline std::unique_ptr<PlantAtlas> attachPlantAtlas(ShaderLibrary& shaders, Renderer& renderer) {
    std::string reason;
    auto atlas = std::make_unique<PlantAtlas>(shaders, choosePlantInterpretation(gl::measureCapabilities(), false, reason));
    renderer.views().setPlantAtlas(atlas.get());
    return atlas;
}

// The terrain height as the GPU evaluates it (shaders/height_probe.frag) at each world point:
// (h, dh/dx, dh/dz). Uses the FrameBlock of the renderer's last frame (its terrain shape and its
// camera: points go to the GPU relative to the camera, subtracted in double, as vertices do).
template <typename Point>
std::vector<glm::vec3> probeGpuHeights(ShaderLibrary& shaders, const Renderer& renderer,
                                       const std::vector<Point>& points) {
    const int side = std::max(1, int(std::ceil(std::sqrt(double(points.size())))));
    const glm::dvec3 camera = renderer.lastFrame().setup.view.pose.position;
    std::vector<float> input(size_t(side) * size_t(side) * 4, 0.0f);
    for (size_t i = 0; i < points.size(); ++i) {
        input[i * 4] = float(double(points[i].x) - camera.x);
        input[i * 4 + 1] = float(double(points[i].y) - camera.z);
    }
    gl::Texture source = gl::createTargetTexture("test source", GL_RGBA32F, side, side);
    glBindTexture(GL_TEXTURE_2D, source.name());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, side, side, GL_RGBA, GL_FLOAT, input.data());
    gl::Texture output = gl::createTargetTexture("test output", GL_RGBA32F, side, side);
    gl::Framebuffer framebuffer = gl::createFramebuffer("test output");
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.name());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, output.name(), 0);
    EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    glViewport(0, 0, side, side);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glClearColor(-1000.0f, -1000.0f, -1000.0f, 0.0f);  // a pixel the probe misses cannot pass
    glClear(GL_COLOR_BUFFER_BIT);
    glActiveTexture(GL_TEXTURE0 + kUnitSource);
    glBindTexture(GL_TEXTURE_2D, source.name());
    glUseProgram(shaders.program("probe.height"));
    renderer.parts().geometry.drawFullscreenTriangle();
    std::vector<float> result(size_t(side) * size_t(side) * 4);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, side, side, GL_RGBA, GL_FLOAT, result.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glUseProgram(0);
    std::vector<glm::vec3> heights;
    for (size_t i = 0; i < points.size(); ++i) {
        EXPECT_EQ(result[i * 4 + 3], 1.0f) << "probe pixel " << i << " not written";
        heights.emplace_back(result[i * 4], result[i * 4 + 1], result[i * 4 + 2]);
    }
    return heights;
}

// Writes the image as a PNG under $OASIS_GPU_TEST_DUMP when set (for looking at failures).
inline void dumpImage(const std::string& name, const Image& image) {
    const char* dir = std::getenv("OASIS_GPU_TEST_DUMP");
    if (!dir || !*dir) return;
    std::string error;
    writePng(std::string(dir) + "/" + name + ".png", image, error);
}

// ---------------------------------------------------------------------------------------------
// Image statistics (8-bit RGB; regions are top-down, half-open [x0, x1) x [y0, y1)).

struct Region {
    int x0, y0, x1, y1;
};
inline Region wholeImage(const Image& image) { return {0, 0, image.width, image.height}; }

struct RgbStats {
    std::array<double, 3> mean{}, stddev{};
    size_t pixels = 0;
    size_t distinctColours = 0;
    double minStddev() const { return std::min({stddev[0], stddev[1], stddev[2]}); }
    double maxStddev() const { return std::max({stddev[0], stddev[1], stddev[2]}); }
    double maxMean() const { return std::max({mean[0], mean[1], mean[2]}); }
};

// Statistics over the region's pixels for which `keep(x, y)` holds (all when keep is empty).
inline RgbStats rgbStats(const Image& image, Region region,
                         const std::function<bool(int, int)>& keep = nullptr) {
    RgbStats stats;
    std::array<double, 3> sum{}, sumSquares{};
    std::set<uint32_t> colours;
    for (int y = region.y0; y < region.y1; ++y) {
        for (int x = region.x0; x < region.x1; ++x) {
            if (keep && !keep(x, y)) continue;
            const uint8_t* p = image.pixel(x, y);
            for (int c = 0; c < 3; ++c) {
                sum[c] += p[c];
                sumSquares[c] += double(p[c]) * p[c];
            }
            colours.insert(uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16);
            ++stats.pixels;
        }
    }
    for (int c = 0; c < 3 && stats.pixels; ++c) {
        stats.mean[c] = sum[c] / double(stats.pixels);
        stats.stddev[c] = std::sqrt(std::max(0.0, sumSquares[c] / double(stats.pixels) - stats.mean[c] * stats.mean[c]));
    }
    stats.distinctColours = colours.size();
    return stats;
}

inline std::string describe(const RgbStats& s) {
    char text[200];
    std::snprintf(text, sizeof(text), "mean (%.2f, %.2f, %.2f) stddev (%.2f, %.2f, %.2f) over %zu px, %zu colours",
                  s.mean[0], s.mean[1], s.mean[2], s.stddev[0], s.stddev[1], s.stddev[2], s.pixels,
                  s.distinctColours);
    return text;
}

// "Has content": more than one colour and every RGB channel varies (stddev in 8-bit units).
constexpr double kMinChannelStddev = 1.0;
inline ::testing::AssertionResult hasContent(const Image& image, double minStddev = kMinChannelStddev) {
    RgbStats stats = rgbStats(image, wholeImage(image));
    if (stats.distinctColours > 1 && stats.minStddev() > minStddev) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "image looks flat: " << describe(stats);
}

inline int countNonFinite(const std::vector<float>& values) {
    return int(std::count_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); }));
}

// An RGBA float buffer pixel (bottom row first, as GL reads it).
inline glm::vec4 texel(const std::vector<float>& rgba, int width, int x, int yFromBottom) {
    size_t i = (size_t(yFromBottom) * size_t(width) + size_t(x)) * 4;
    return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
}

// A display pixel at GL coordinates (bottom row first), from the top-down image.
inline glm::ivec3 displayPixel(const Image& image, int x, int yFromBottom) {
    const uint8_t* p = image.pixel(x, image.height - 1 - yFromBottom);
    return {p[0], p[1], p[2]};
}

inline glm::ivec3 to8bit(glm::vec3 colour) {
    glm::vec3 c = glm::clamp(colour, glm::vec3(0.0f), glm::vec3(1.0f)) * 255.0f;
    return {int(std::lround(c.x)), int(std::lround(c.y)), int(std::lround(c.z))};
}

inline int maxChannelDifference(glm::ivec3 a, glm::ivec3 b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

inline std::string str(glm::ivec3 c) {
    return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ", " + std::to_string(c.z) + ")";
}

// Position tolerance from D24 depth. Window depth z_w = 0.5 + 0.5 z_ndc with
// z_ndc = (f+n)/(f-n) - 2fn / ((f-n) d) for eye depth d, so one D24 step (1/(2^24-1) in z_w) moves
// the reconstructed point along its ray by  step(d) = d^2 (f-n) / (f n (2^24-1))  ~=  d^2 / (n 2^24)
// (n = 0.25, f = 6000: 0.06 at d = 500, 0.95 at d = 2000). The errors that scale the same way:
// D24 rounding (<= 1 step), z_ndc computed in float32 in the vertex shader, where z_ndc is close
// to 1 and its ulp is half a step (clip z and w and their divide: ~2 steps), and the float32
// entries of inverseViewProjection used for the reconstruction (~1 step). Allowed: 5 steps, plus
// 1e-4 relative for the float32 position/interpolation and 1 mm. Measured worst: 3.3 steps (default). A
// position off by one pixel sideways (3.2 units at d = 500) or by a wrong origin is far outside.
inline double depthStep(double eyeDistance, double nearPlane, double farPlane) {
    return eyeDistance * eyeDistance * (farPlane - nearPlane) / (farPlane * nearPlane * 16777215.0);
}
inline double reconstructionTolerance(double eyeDistance, double nearPlane, double farPlane) {
    return 5.0 * depthStep(eyeDistance, nearPlane, farPlane) + 1e-4 * eyeDistance + 1e-3;
}
// Surface flags (shaders/common/shared_constants.glsl) and their decoding from an info texel.
constexpr unsigned kSurfaceSky = OASIS_SURFACE_SKY, kSurfaceReflected = OASIS_SURFACE_REFLECTED,
                   kSurfacePlant = OASIS_SURFACE_PLANT;
// The flags of an info texel in the layouts that store the surface as is (full, standard); the
// layout table decodes every encoding (GBufferLayout::storedFlags).
inline unsigned infoFlags(glm::vec4 info) { return findGBufferLayout("standard")->storedFlags(info); }

// Stencil marks (passes/pass.h: StencilMark).
constexpr uint8_t kStencilSky = 0, kStencilTerrain = 1, kStencilWater = 2, kStencilPlant = 3;

// Whether a whole frame wrote a colour target's texel (and below: the non-finite values among
// those, and a target with the rest set to 0). Nothing clears a target where no pass writes it (issue 30, item 6): the G-buffer's colour
// targets are written where a surface is the nearest (stencil terrain or plant; at the water's
// pixels they hold the mirrored scene, or where it reflects the sky whatever was there), Reflection
// at the water's pixels with reflections active; the other targets everywhere. Elsewhere a target
// holds an earlier frame's values or fresh memory (NaNs on zink), which nothing reads.
inline bool texelWritten(Target target, uint8_t stencil, bool reflectionsActive) {
    uint8_t mark = stencil & 0x7f;
    if (target == Target::Albedo || target == Target::Normal || target == Target::Position || target == Target::Info)
        return mark == kStencilTerrain || mark == kStencilPlant;
    if (target == Target::Reflection) return reflectionsActive && mark == kStencilWater;
    return true;
}
inline int countNonFiniteWritten(const std::vector<float>& values, Target target, const std::vector<uint8_t>& stencil,
                                 bool reflectionsActive) {
    int count = 0;
    for (size_t i = 0; i < stencil.size(); ++i)
        for (size_t c = 0; texelWritten(target, stencil[i], reflectionsActive) && c < 4; ++c)
            count += std::isfinite(values[i * 4 + c]) ? 0 : 1;
    return count;
}
// The same target with the texels the frame did not write set to 0, for comparing two frames.
inline std::vector<float> writtenTexels(std::vector<float> values, Target target, const std::vector<uint8_t>& stencil,
                                        bool reflectionsActive) {
    for (size_t i = 0; i < stencil.size(); ++i)
        if (!texelWritten(target, stencil[i], reflectionsActive))
            for (size_t c = 0; c < 4; ++c) values[i * 4 + c] = 0.0f;
    return values;
}
// Sets a colour target to 0 everywhere before a frame, so that a test can tell the texels the
// frame writes from those it leaves (which nothing clears: fresh memory holds NaNs on zink).
inline void zeroTarget(const FrameTargets& targets, Target target) {
    bindFramebufferOf(targets, {{target, Use::Write}});
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, zero);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}
// Nothing drawn at a pixel, as gbufferSkyAt tells it (shaders/common/gbuffer.glsl): the depth at the
// far plane in the layouts that rebuild position from it (compact; its Info is not cleared), Info's
// SKY flag in the others.
inline bool nothingDrawn(const GBufferLayout& layout, glm::vec4 info, float depth, float farPlaneWindowDepth) {
    if (layout.positionFromDepth()) return depth == farPlaneWindowDepth;
    return (layout.storedFlags(info) & OASIS_SURFACE_SKY) != 0u;
}

// ---------------------------------------------------------------------------------------------
// Frame geometry on the CPU, in double, from the frame's own matrices.

// One D24 step of window depth.
constexpr double kDepthStep = 1.0 / 16777215.0;

// The camera-relative world direction of the ray through a pixel centre (x, y from bottom).
inline glm::dvec3 pixelRay(const FrameData& frame, int width, int height, double x, double yFromBottom) {
    glm::dmat4 inverse(frame.inverseViewProjection);
    glm::dvec4 far = inverse * glm::dvec4(x / width * 2.0 - 1.0, yFromBottom / height * 2.0 - 1.0, 1.0, 1.0);
    return glm::normalize(glm::dvec3(far) / far.w);
}
inline glm::dvec3 pixelRay(const FrameData& frame, int width, int height, int x, int yFromBottom) {
    return pixelRay(frame, width, height, x + 0.5, yFromBottom + 0.5);
}

// A camera-relative point projected with the frame's viewProjection: window x, y (pixels) and z.
inline glm::dvec3 project(const FrameData& frame, int width, int height, glm::dvec3 relative) {
    glm::dvec4 clip = glm::dmat4(frame.viewProjection) * glm::dvec4(relative, 1.0);
    glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    return {(ndc.x * 0.5 + 0.5) * width, (ndc.y * 0.5 + 0.5) * height, ndc.z * 0.5 + 0.5};
}

// The camera-relative point a window depth reconstructs at a pixel centre.
inline glm::dvec3 unproject(const FrameData& frame, int width, int height, int x, int yFromBottom, double depth) {
    glm::dvec4 ndc((x + 0.5) / width * 2.0 - 1.0, (yFromBottom + 0.5) / height * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    glm::dvec4 world = glm::dmat4(frame.inverseViewProjection) * ndc;
    return glm::dvec3(world) / world.w;
}

// Where a camera-relative ray meets the water plane (false if it does not, ahead of the camera).
inline bool rayMeetsWater(const FrameData& frame, glm::dvec3 ray, glm::dvec3& hit) {
    double height = double(frame.water.x) - double(frame.cameraPosition.y);  // plane relative to the eye
    if (ray.y == 0.0 || height / ray.y <= 0.0) return false;
    hit = ray * (height / ray.y);
    return true;
}

// Linear RGB of a float target at a pixel.
inline glm::vec3 rgbAt(const std::vector<float>& rgba, int width, int x, int yFromBottom) {
    return glm::vec3(texel(rgba, width, x, yFromBottom));
}

}  // namespace oasis::gputest
