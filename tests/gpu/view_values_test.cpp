// The numbers behind the views (VIEW_VALUES passes) against the targets read back on the CPU, in
// every layout; a NaN written into Radiance is counted and painted by the overlay; the legend
// strip draws the depth view's ramp with the frame's near and far planes.
#include "frame/frame_readback.h"
#include "gpu_test.h"

#include "debug/view_controls.h"
#include "debug/view_legend.h"

namespace oasis::gputest {
namespace {


class ViewValues : public GpuTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(ViewValues, AreTheTargetsDecoded) {
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    const GBufferLayout& layout = layoutNamed(GetParam());
    renderer.configure(kSmallWidth, kSmallHeight, layout);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.renderFrame(pose.scene);
    renderer.views().ensureGBuffer();  // the targets as the views show them (the direct scene under the water)
    const std::vector<float> positions = readSurfacePositions(renderer);
    const std::vector<float> normal = readTarget(renderer, Target::Normal);
    const std::vector<float> info = readTarget(renderer, Target::Info);
    const std::vector<float> radiance = readTarget(renderer, Target::Radiance);
    const std::vector<float> depth = readDepth(renderer);
    const std::vector<uint8_t> stencil = readStencil(renderer);
    const FrameData& frame = renderer.lastFrame().setup.data;
    const double nearPlane = frame.depthRange.x, farPlane = frame.depthRange.y;

    const std::vector<float> positionValues = renderer.views().readValues("position");
    const std::vector<float> normalValues = renderer.views().readValues("normal");
    const std::vector<float> depthValues = renderer.views().readValues("depth");
    const std::vector<float> stencilValues = renderer.views().readValues("stencil");
    const std::vector<float> radianceValues = renderer.views().readValues("radiance");
    int positionOff = 0, normalOff = 0, depthOff = 0, stencilOff = 0, radianceOff = 0, surfaces = 0;
    for (int y = 0; y < kSmallHeight; ++y)
        for (int x = 0; x < kSmallWidth; ++x) {
            size_t i = size_t(y) * kSmallWidth + size_t(x);
            bool sky = nothingDrawn(layout, texel(info, kSmallWidth, x, y), depth[i], renderer.targets().depth().farPlaneWindowDepth);
            glm::vec4 p = texel(positions, kSmallWidth, x, y), pv = texel(positionValues, kSmallWidth, x, y);
            if (sky ? pv != glm::vec4(0.0f)
                    : glm::distance(glm::vec3(p), glm::vec3(pv)) > 1e-5f * (1.0f + glm::length(glm::vec3(p))) ||
                          std::fabs(pv.w - glm::length(glm::vec3(p))) > 1e-4f * (1.0f + pv.w))
                ++positionOff;
            if (!sky) {
                ++surfaces;
                glm::vec3 n = layout.storedNormal(texel(normal, kSmallWidth, x, y));
                if (glm::distance(n, glm::vec3(texel(normalValues, kSmallWidth, x, y))) > 2e-5f) ++normalOff;
            }
            // Depth: eye distance along the view axis (standard depth: the NDC formula), window depth.
            double d = depth[i], ndc = d * 2.0 - 1.0;
            double eye = 2.0 * nearPlane * farPlane / (farPlane + nearPlane - ndc * (farPlane - nearPlane));
            glm::vec4 dv = texel(depthValues, kSmallWidth, x, y);
            if (std::fabs(dv.x - eye) > 1e-3 * eye || std::fabs(dv.y - d) > 1e-7) ++depthOff;
            if (texel(stencilValues, kSmallWidth, x, y).x != float(stencil[i])) ++stencilOff;
            if (texel(radianceValues, kSmallWidth, x, y) != texel(radiance, kSmallWidth, x, y)) ++radianceOff;
        }
    EXPECT_GT(surfaces, kSmallWidth * kSmallHeight / 2);
    EXPECT_EQ(positionOff, 0);
    EXPECT_EQ(normalOff, 0);
    EXPECT_EQ(depthOff, 0);
    EXPECT_EQ(stencilOff, 0);
    EXPECT_EQ(radianceOff, 0);
    // Every view fills the channels its table row names and leaves the frame's numbers finite.
    for (const DebugView& view : debugViews()) {
        ValueStatistics s = valueStatistics(renderer.views().readValues(view.name), defaultChannel(view));
        EXPECT_EQ(s.nan + s.positiveInfinity + s.negativeInfinity, 0) << view.name;
        EXPECT_TRUE(s.anyFinite) << view.name;
    }
}

INSTANTIATE_TEST_SUITE_P(Layouts, ViewValues, ::testing::Values("full", "standard", "compact"),
                         [](const auto& info) { return info.param; });

// A NaN in Radiance (as a broken shader would leave) is counted on every pixel and painted by the
// overlay in the view's own colours and in the values; turned off, nothing is painted.
TEST_F(GpuTest, NanInRadianceIsCountedAndOverlaid) {
    SceneSettings scene = defaultPose().scene;
    Renderer renderer(*shaders_, scene);
    renderer.configure(64, 36, layoutNamed("compact"));
    renderer.renderFrame(scene);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const GLfloat poisoned[4] = {nan, 0.5f, nan, 1.0f};
    glBindFramebuffer(GL_FRAMEBUFFER, renderer.targets().framebuffer({Target::Radiance}, Target::DepthStencil));
    glClearBufferfv(GL_COLOR, 0, poisoned);
    std::vector<float> values = renderer.views().readValues("radiance");
    ValueStatistics rgb = valueStatistics(values, ViewChannel::Rgb);
    EXPECT_EQ(rgb.nan, 64 * 36 * 2);
    EXPECT_EQ(valueStatistics(values, ViewChannel::G).nan, 0);
    renderer.views().render("radiance");
    Image view = readDisplay(renderer);
    paintOverlay(view, values, ViewChannel::Rgb, kOverlayNan);
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 64; ++x) {
            const uint8_t* p = view.pixel(x, y);
            bool magenta = p[0] == 255 && p[1] == 0 && p[2] == 255, black = p[0] == 0 && p[1] == 0 && p[2] == 0;
            ASSERT_TRUE(magenta || black) << x << "," << y;
        }
    Image unpainted = readDisplay(renderer);
    Image copy = unpainted;
    paintOverlay(copy, values, ViewChannel::G, kOverlayNan);  // g has no NaN
    EXPECT_TRUE(copy.rgba == unpainted.rgba);
}

// The depth view's legend: its bar samples the view's ramp (depthRampColour, the twin of the
// shader's) from the near to the far plane, on a strip of the image's width.
TEST_F(GpuTest, DepthLegendDrawsTheViewsRamp) {
    LegendRenderer legends;
    Legend legend = viewLegend(*findDebugView("depth"), ViewControls{}, ValueStatistics{}, 0.25, 6000.0, 4000.0);
    EXPECT_EQ(legend.scale, LegendScale::DepthRamp);
    Image strip = legends.draw(legend, 640);
    ASSERT_EQ(strip.width, 640);
    ASSERT_GT(strip.height, 40);
    dumpImage("legend-depth", strip);
    // Find the bar: the row where the middle pixel has the ramp's middle colour.
    uint8_t middle[3];
    depthRampColour(0.5f, middle);
    int barRow = -1;
    for (int y = 0; y < strip.height && barRow < 0; ++y) {
        const uint8_t* p = strip.pixel(320, y);
        if (std::abs(p[0] - middle[0]) <= 6 && std::abs(p[1] - middle[1]) <= 6 && std::abs(p[2] - middle[2]) <= 6)
            barRow = y;
    }
    ASSERT_GE(barRow, 0) << "no ramp bar in the legend";
    for (float t : {0.1f, 0.3f, 0.7f, 0.9f}) {
        uint8_t want[3];
        depthRampColour(t, want);
        const uint8_t* got = strip.pixel(int(4 + t * (640 - 8)), barRow);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 8) << "t " << t << " channel " << c;
    }
    EXPECT_TRUE(hasContent(strip));
}

}  // namespace
}  // namespace oasis::gputest
