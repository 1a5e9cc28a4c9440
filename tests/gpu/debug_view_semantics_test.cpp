// Debug views: each view's colours follow its remapping in shaders/debug_view.frag, checked on
// every pixel against the targets read back, in every G-buffer layout.
#include "debug_views_support.h"

#include "render/plant_atlas.h"

namespace oasis::gputest {
namespace {


// The atlas view samples the plant atlas (nearest) rather than a frame target: of the atlas texels
// at and next to where pixel (x, y) of a width x height view samples (the sample position may round
// either way at a texel edge), the one closest to `got` (top-down image coordinates).
glm::ivec3 atlasTexelFor(const Image& atlas, int x, int y, int width, int height, glm::ivec3 got) {
    int ax = int(std::floor((x + 0.5) / width * atlas.width));
    int ay = int(std::floor((y + 0.5) / height * atlas.height));
    glm::ivec3 best(-1000);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const uint8_t* p = atlas.pixel(std::clamp(ax + dx, 0, atlas.width - 1), std::clamp(ay + dy, 0, atlas.height - 1));
            glm::ivec3 texel(p[0], p[1], p[2]);
            if (maxChannelDifference(texel, got) < maxChannelDifference(best, got)) best = texel;
        }
    return best;
}

// Each view's colours follow its remapping in shaders/debug_view.frag, checked on every pixel
// against the targets read back (8-bit rounding: +-1, the stencil colour +-2). The default frame
// shows the lake, so reflected surfaces (info blue 0.5) and water stencil (2) are covered.
class DebugViewSemantics : public GpuTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(DebugViewSemantics, ViewsFollowTheirRemapping) {
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    const GBufferLayout& layout = layoutNamed(GetParam());
    renderer.configure(kMediumWidth, kMediumHeight, layout);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    const Image atlasImage = atlas->read();
    renderer.setPipeline(PipelineKind::Deferred);
    // Earlier frames leave stale texels where this one writes none (the colour targets are not
    // cleared): the lake mirrored over other pixels in Reflection, then surfaces in every G-buffer
    // texel (looking down). The views must show none of them.
    renderer.renderFrame(poseNamed("lakeMirror").scene);
    renderer.renderFrame(poseNamed("down").scene);
    renderer.renderFrame(pose.scene);
    renderer.views().ensureGBuffer();  // the targets as the views show them (the direct scene under the water)
    const std::vector<float> albedo = readTarget(renderer, Target::Albedo);
    const std::vector<float> normal = readTarget(renderer, Target::Normal);
    // Stored, or reconstructed from depth by the GPU as lighting does (the compact layout).
    const std::vector<float> position = readSurfacePositions(renderer);
    const std::vector<float> info = readTarget(renderer, Target::Info);
    const std::vector<float> final = readTarget(renderer, Target::Final);
    const std::vector<float> reflection = readTarget(renderer, Target::Reflection);
    const std::vector<float> radiance = readTarget(renderer, Target::Radiance);
    const std::vector<float> depth = readDepth(renderer);
    const std::vector<uint8_t> stencil = readStencil(renderer);
    const FrameData& frame = renderer.lastFrame().setup.data;
    const float exposure = frame.depthRange.w;
    const float nearPlane = frame.depthRange.x, farPlane = frame.depthRange.y;
    const float viewDistance = frame.terrainGridCounts.w;
    // Nothing drawn (gbufferSkyAt): the compact layout tells it by depth at the far plane, its colour
    // targets not cleared there; the others by Info's SKY flag. The views show the flags SKY there.
    auto skyAt = [&](int x, int y) {
        if (layout.positionFromDepth()) return depth[size_t(y) * kMediumWidth + size_t(x)] >= 1.0f;
        return (layout.storedFlags(texel(info, kMediumWidth, x, y)) & kSurfaceSky) != 0u;
    };
    auto flagsAt = [&](int x, int y) { return skyAt(x, y) ? kSurfaceSky : layout.storedFlags(texel(info, kMediumWidth, x, y)); };
    auto normalAt = [&](int x, int y) { return layout.storedNormal(texel(normal, kMediumWidth, x, y)); };

    std::map<std::string, Image> images;
    for (const DebugView& view : debugViews()) {
        renderer.views().render(view.name);
        images[view.name] = readDisplay(renderer);
        ASSERT_TRUE(hasContent(images[view.name])) << view.name;
    }

    auto ramp = [](float t) {
        t = std::clamp(t, 0.0f, 1.0f);
        glm::vec3 low(0.05f, 0.03f, 0.25f), mid(0.10f, 0.60f, 0.55f), high(0.99f, 0.91f, 0.15f);
        return t < 0.5f ? glm::mix(low, mid, t * 2.0f) : glm::mix(mid, high, t * 2.0f - 1.0f);
    };
    // name -> (expected colour, tolerance) of pixel (x, y from bottom)
    std::map<std::string, std::function<std::pair<glm::ivec3, int>(int, int)>> expected;
    expected["atlas"] = [&](int x, int y) {  // y from the bottom
        glm::ivec3 got = displayPixel(images["atlas"], x, y);
        return std::make_pair(atlasTexelFor(atlasImage, x, kMediumHeight - 1 - y, kMediumWidth, kMediumHeight, got), 0);
    };
    expected["final"] = [&](int x, int y) { return std::make_pair(to8bit(glm::vec3(texel(final, kMediumWidth, x, y))), 0); };
    expected["albedo"] = [&](int x, int y) {
        if (skyAt(x, y)) return std::make_pair(glm::ivec3(0), 0);  // black where nothing was drawn
        glm::vec3 a(texel(albedo, kMediumWidth, x, y));
        return std::make_pair(to8bit(glm::pow(glm::clamp(a, 0.0f, 1.0f), glm::vec3(1.0f / 2.2f))), 1);
    };
    expected["normal"] = [&](int x, int y) {
        if (flagsAt(x, y) & kSurfaceSky) return std::make_pair(glm::ivec3(128), 1);  // the cleared (0, 0, 0)
        glm::vec3 n = normalAt(x, y);
        return std::make_pair(to8bit(0.5f + 0.5f * glm::clamp(n, -1.0f, 1.0f)), 1);
    };
    expected["position"] = [&](int x, int y) {
        glm::vec4 p = texel(position, kMediumWidth, x, y);
        if (p.w == 0.0f) return std::make_pair(glm::ivec3(0), 0);
        glm::vec3 v(p);
        glm::vec3 scaled = glm::sign(v) * glm::log(1.0f + glm::abs(v)) / std::log(1.0f + viewDistance);
        return std::make_pair(to8bit(0.5f + 0.5f * glm::clamp(scaled, -1.0f, 1.0f)), 1);
    };
    expected["info"] = [&](int x, int y) {
        glm::vec4 i = texel(info, kMediumWidth, x, y);
        if (flagsAt(x, y) & kSurfaceSky) return std::make_pair(glm::ivec3(0, 0, 204), 0);
        float flagMarks = ((flagsAt(x, y) & kSurfaceReflected) ? 0.5f : 0.0f) + ((flagsAt(x, y) & kSurfacePlant) ? 0.25f : 0.0f);
        float intensity = layout.encoding == GBufferEncoding::Compact ? texel(albedo, kMediumWidth, x, y).a : i.g;
        return std::make_pair(to8bit({std::round(i.r * 255.0f) / 64.0f, intensity / 0.25f, flagMarks}), 1);
    };
    expected["depth"] = [&](int x, int y) {
        float d = depth[size_t(y) * kMediumWidth + size_t(x)];
        if (d >= 1.0f) return std::make_pair(glm::ivec3(0), 0);
        float ndc = d * 2.0f - 1.0f;
        float eye = 2.0f * nearPlane * farPlane / (farPlane + nearPlane - ndc * (farPlane - nearPlane));
        return std::make_pair(to8bit(ramp(std::log(eye / nearPlane) / std::log(farPlane / nearPlane))), 1);
    };
    expected["stencil"] = [&](int x, int y) {
        uint8_t s = stencil[size_t(y) * kMediumWidth + size_t(x)];
        if (s == 0) return std::make_pair(glm::ivec3(0), 0);
        if (s == 2) return std::make_pair(glm::ivec3(38, 115, 242), 2);  // water (0.15, 0.45, 0.95)
        if (s == 3) return std::make_pair(glm::ivec3(51, 217, 89), 2);   // plants (0.20, 0.85, 0.35)
        EXPECT_EQ(s, 1) << "only terrain (1), water (2) and plants (3) write stencil";
        return std::make_pair(glm::ivec3(242, 158, 31), 2);  // terrain (0.95, 0.62, 0.12)
    };
    expected["vegetation"] = [&](int x, int y) {
        unsigned flags = flagsAt(x, y);
        bool plant = (flags & kSurfacePlant) && !(flags & kSurfaceReflected);
        return std::make_pair(plant ? to8bit(glm::vec3(texel(final, kMediumWidth, x, y))) : glm::ivec3(0), 0);
    };
    expected["light-volumes"] = [&](int x, int y) {
        // No lights in this frame: dark grey by the normal's slope on surfaces, black sky.
        if (flagsAt(x, y) & kSurfaceSky) return std::make_pair(glm::ivec3(0), 0);
        float grey = 0.05f + 0.1f * std::clamp(normalAt(x, y).y, 0.0f, 1.0f);
        return std::make_pair(to8bit(glm::vec3(grey)), 1);
    };
    // The sun's shadow: a hue per cascade (grey for none) darkened by the lit fraction, from the
    // view's own numbers, which must be in range and whose n.l is the G-buffer normal's.
    const std::vector<float> shadowValues = renderer.views().readValues("shadow");
    const glm::vec3 toSun(frame.sunDirection);
    int shadowValuesWrong = 0;
    expected["shadow"] = [&](int x, int y) {
        if (flagsAt(x, y) & kSurfaceSky) return std::make_pair(glm::ivec3(0), 0);
        glm::vec4 v = texel(shadowValues, kMediumWidth, x, y);
        int cascade = int(std::lround(v.y));
        glm::vec3 n = glm::normalize(normalAt(x, y));
        if (v.x < 0.0f || v.x > 1.0f || cascade < -1 || cascade >= OASIS_SHADOW_MAX_CASCADES ||
            std::fabs(v.z - glm::dot(n, toSun)) > 0.02f)
            ++shadowValuesWrong;
        const glm::vec3 hues[4] = {{1.0f, 0.3f, 0.25f}, {0.3f, 1.0f, 0.3f}, {0.3f, 0.45f, 1.0f}, {1.0f, 0.9f, 0.2f}};
        glm::vec3 hue = cascade < 0 || cascade > 3 ? glm::vec3(0.6f) : hues[cascade];
        return std::make_pair(to8bit(hue * (0.15f + 0.85f * v.x)), 1);
    };
    // Reflection is not cleared (written at the water's pixels only): its views read it inside the
    // water (stencil 2) and are black elsewhere.
    auto reflectionAt = [&](int x, int y) {
        bool water = stencil[size_t(y) * kMediumWidth + size_t(x)] == kStencilWater;
        return water ? texel(reflection, kMediumWidth, x, y) : glm::vec4(0.0f);
    };
    expected["reflection"] = [&](int x, int y) {
        // Tone-mapped like Final (shaders/common/output.glsl); black outside the water.
        glm::vec3 r(reflectionAt(x, y));
        glm::vec3 mapped = glm::vec3(1.0f) - glm::exp(-glm::max(r, glm::vec3(0.0f)) * exposure);
        return std::make_pair(to8bit(glm::pow(mapped, glm::vec3(1.0f / 2.2f))), 1);
    };

    // The HDR views: linear light times 2^stops (0 stops here), gamma 2.2, clipped at 1.
    auto hdr = [](glm::vec4 light) {
        return to8bit(glm::pow(glm::clamp(glm::vec3(light), 0.0f, 1.0f), glm::vec3(1.0f / 2.2f)));
    };
    expected["radiance"] = [&](int x, int y) { return std::make_pair(hdr(texel(radiance, kMediumWidth, x, y)), 1); };
    expected["reflection-raw"] = [&](int x, int y) { return std::make_pair(hdr(reflectionAt(x, y)), 1); };

    int reflectionViewOutsideWater = 0, stencilWater = 0;
    for (int y = 0; y < kMediumHeight; ++y)
        for (int x = 0; x < kMediumWidth; ++x) {
            bool water = stencil[size_t(y) * kMediumWidth + size_t(x)] == kStencilWater;
            stencilWater += water ? 1 : 0;
            for (const char* view : {"reflection", "reflection-raw"})
                if (!water && displayPixel(images[view], x, y) != glm::ivec3(0)) ++reflectionViewOutsideWater;
        }
    EXPECT_EQ(reflectionViewOutsideWater, 0) << "a Reflection view not black outside the water (stencil != 2)";
    EXPECT_GT(stencilWater, 0) << "the default frame should show the lake";

    for (const DebugView& view : debugViews()) {
        ASSERT_TRUE(expected.count(view.name)) << "no semantic check for view " << view.name;
        int wrong = 0, black = 0;
        std::string first;
        for (int y = 0; y < kMediumHeight; ++y) {
            for (int x = 0; x < kMediumWidth; ++x) {
                auto [want, tolerance] = expected[view.name](x, y);
                glm::ivec3 got = displayPixel(images[view.name], x, y);
                if (got == glm::ivec3(0)) ++black;
                if (maxChannelDifference(got, want) > tolerance && wrong++ == 0)
                    first = "(" + std::to_string(x) + ", " + std::to_string(y) + " from bottom): got " + str(got) +
                            ", expected " + str(want);
            }
        }
        EXPECT_EQ(wrong, 0) << view.name << " view: " << wrong << " pixels off; first " << first;
        if (view.name == "depth") {
            // Black exactly where depth == 1 (the ramp never reaches black).
            int cleared = int(std::count(depth.begin(), depth.end(), 1.0f));
            EXPECT_EQ(black, cleared) << "depth view black pixels vs cleared depth";
            EXPECT_GT(cleared, 0);
        }
    }

    EXPECT_EQ(shadowValuesWrong, 0) << "shadow view values out of range, or n.l not the G-buffer normal's";

    // The exposure control: +2 stops shows Radiance four times as bright (before the clip at 1).
    renderer.views().setExposure(2.0f);
    renderer.views().render("radiance");
    Image brighter = readDisplay(renderer);
    renderer.views().setExposure(0.0f);
    int exposureOff = 0;
    for (int y = 0; y < kMediumHeight; ++y)
        for (int x = 0; x < kMediumWidth; ++x)
            if (maxChannelDifference(displayPixel(brighter, x, y), hdr(4.0f * texel(radiance, kMediumWidth, x, y))) > 1)
                ++exposureOff;
    EXPECT_EQ(exposureOff, 0) << "radiance view at +2 stops";
    EXPECT_GT(compareImages(brighter, images["radiance"]).maxAbs, 20) << "the exposure changed nothing";

    // The stencil view through stencil texturing equals the CPU read-back path bit for bit,
    // alone and inside the overview.
    for (const std::string& name : {std::string("stencil"), std::string(kOverviewName)}) {
        renderer.views().setStencilPath(StencilViewPath::Texturing);
        renderer.views().render(name);
        Image texturing = readDisplay(renderer);
        renderer.views().setStencilPath(StencilViewPath::ReadBack);
        renderer.views().render(name);
        Image readBack = readDisplay(renderer);
        EXPECT_TRUE(texturing.rgba == readBack.rgba) << name << ": stencil texturing and read-back differ (max "
                                                     << compareImages(texturing, readBack).maxAbs << ")";
        EXPECT_TRUE(hasContent(readBack)) << name;
    }
}

INSTANTIATE_TEST_SUITE_P(Layouts, DebugViewSemantics, ::testing::Values("full", "standard", "compact"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace oasis::gputest
