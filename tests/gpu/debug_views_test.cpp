// Debug views: every view and the overview have content in both pipelines (forward's G-buffer
// views equal deferred's), each view's colours follow its remapping, the two stencil paths agree
// bit for bit, and every overview tile shows its view under its label.
#include "gpu_test.h"

#include "debug/debug_views.h"

namespace oasis::gputest {
namespace {

constexpr int kWidth = 320, kHeight = 180;

std::vector<std::string> allViewNames() {
    std::vector<std::string> names;
    for (const DebugView& view : debugViews()) names.push_back(view.name);
    names.push_back(kOverviewName);
    return names;
}

// The overview's grid, as debug/debug_view_pass.cpp lays it out (top-down image coordinates).
struct OverviewTile {
    Region area;      // the pixels the tile's view covers (one pixel in from the grid cell)
    Region label;     // generous box around the tile's label (empty when labels are not drawn)
};
std::vector<OverviewTile> overviewTiles(int width, int height) {
    size_t count = debugViews().size();
    int columns = int(std::ceil(std::sqrt(double(count))));
    int rows = int((count + size_t(columns) - 1) / size_t(columns));
    int tileWidth = width / columns, tileHeight = height / rows;
    float scale = std::max(1.0f, float(tileHeight) / 200.0f);
    std::vector<OverviewTile> tiles;
    for (size_t i = 0; i < count; ++i) {
        int x = int(i) % columns * tileWidth, y = int(i) / columns * tileHeight;
        OverviewTile tile;
        tile.area = {x + 1, y + 1, x + tileWidth - 1, y + tileHeight - 1};
        // ImGui's default font: 13 px high, 7 px advance; 3 px padding at scale 1; label at (+4, +4).
        int labelWidth = int(std::ceil((8.0f * float(debugViews()[i].name.size()) + 10.0f) * scale)) + 4;
        int labelHeight = int(std::ceil(24.0f * scale)) + 4;
        tile.label = tileHeight >= 24 ? Region{x, y, std::min(x + labelWidth, x + tileWidth), std::min(y + labelHeight, y + tileHeight)}
                                      : Region{x, y, x, y};
        tiles.push_back(tile);
    }
    return tiles;
}
bool inside(const Region& r, int x, int y) { return x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1; }

class DebugViews : public GpuTest {};

// Every view and the overview show content in both pipelines. Forward draws no G-buffer, so its
// G-buffer views come from the geometry passes the renderer runs on demand: they must be exactly
// the deferred frame's, even when the G-buffer still holds another (deferred) frame.
TEST_F(DebugViews, EveryViewHasContentInBothPipelinesAndForwardEqualsDeferred) {
    NamedPose pose = defaultPose();
    NamedPose other = poseNamed("sunset");
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kWidth, kHeight, layoutNamed("standard"));
    std::vector<OverviewTile> tiles = overviewTiles(kWidth, kHeight);
    for (const std::string& name : allViewNames()) {
        SCOPED_TRACE("view " + name);
        Image deferred = renderView(renderer, pose.scene, PipelineKind::Deferred, name);
        renderer.renderFrame(other.scene);  // leave a different deferred frame in the G-buffer
        Image forward = renderView(renderer, pose.scene, PipelineKind::Forward, name);
        dumpImage("view-" + name + "-deferred", deferred);
        dumpImage("view-" + name + "-forward", forward);
        EXPECT_TRUE(hasContent(deferred)) << "deferred";
        EXPECT_TRUE(hasContent(forward)) << "forward";

        ImageDifference difference = compareImages(deferred, forward);
        if (name == "final") {
            EXPECT_GE(difference.psnrDb, 45.0) << "final view: forward and deferred disagree";
        } else if (name == kOverviewName) {
            // Every tile but the lit frame's (tile 0) must be identical.
            int differing = 0;
            for (int y = 0; y < kHeight; ++y)
                for (int x = 0; x < kWidth; ++x)
                    if (!inside(tiles[0].area, x, y) &&
                        maxChannelDifference(displayPixel(deferred, x, kHeight - 1 - y), displayPixel(forward, x, kHeight - 1 - y)) != 0)
                        ++differing;
            EXPECT_EQ(differing, 0) << "overview tiles other than 'final' differ between the pipelines";
            EXPECT_GE(difference.psnrDb, 45.0);
        } else {
            EXPECT_EQ(difference.maxAbs, 0) << "forward and deferred show different " << name << " (PSNR "
                                            << difference.psnrDb << " dB)";
        }
    }
}

// Filling the G-buffer for a view of a forward frame must not change the forward frame.
TEST_F(DebugViews, GBufferViewOfForwardFrameKeepsFinalDepthAndStencil) {
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kWidth, kHeight, layoutNamed("standard"));
    Image before = renderView(renderer, pose.scene, PipelineKind::Forward, "final");
    std::vector<float> depthBefore = renderer.readDepth();
    std::vector<uint8_t> stencilBefore = renderer.readStencil();
    ASSERT_TRUE(hasContent(before));
    renderer.renderView("albedo");
    ASSERT_TRUE(hasContent(renderer.readDisplay()));
    renderer.renderView("final");
    Image after = renderer.readDisplay();
    EXPECT_EQ(compareImages(before, after).maxAbs, 0) << "the forward frame's Final changed";
    EXPECT_TRUE(renderer.readDepth() == depthBefore) << "the forward frame's depth changed";
    EXPECT_TRUE(renderer.readStencil() == stencilBefore) << "the forward frame's stencil changed";
}

// Each view's colours follow its remapping in shaders/debug_view.frag, checked on every pixel
// against the targets read back (8-bit rounding: +-1, the stencil colour +-2).
class DebugViewSemantics : public GpuTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(DebugViewSemantics, ViewsFollowTheirRemapping) {
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kWidth, kHeight, layoutNamed(GetParam()));
    renderer.setPipeline(PipelineKind::Deferred);
    renderer.renderFrame(pose.scene);
    const std::vector<float> albedo = renderer.readTarget(Target::Albedo);
    const std::vector<float> normal = renderer.readTarget(Target::Normal);
    const std::vector<float> position = renderer.readTarget(Target::Position);
    const std::vector<float> info = renderer.readTarget(Target::Info);
    const std::vector<float> final = renderer.readTarget(Target::Final);
    const std::vector<float> depth = renderer.readDepth();
    const std::vector<uint8_t> stencil = renderer.readStencil();
    const FrameData& frame = renderer.lastFrame().data;
    const float nearPlane = frame.depthRange.x, farPlane = frame.depthRange.y;
    const float viewDistance = frame.terrainGridCounts.w;

    std::map<std::string, Image> images;
    for (const DebugView& view : debugViews()) {
        renderer.renderView(view.name);
        images[view.name] = renderer.readDisplay();
        ASSERT_TRUE(hasContent(images[view.name])) << view.name;
    }

    auto ramp = [](float t) {
        t = std::clamp(t, 0.0f, 1.0f);
        glm::vec3 low(0.05f, 0.03f, 0.25f), mid(0.10f, 0.60f, 0.55f), high(0.99f, 0.91f, 0.15f);
        return t < 0.5f ? glm::mix(low, mid, t * 2.0f) : glm::mix(mid, high, t * 2.0f - 1.0f);
    };
    // name -> (expected colour, tolerance) of pixel (x, y from bottom)
    std::map<std::string, std::function<std::pair<glm::ivec3, int>(int, int)>> expected;
    expected["final"] = [&](int x, int y) { return std::make_pair(to8bit(glm::vec3(texel(final, kWidth, x, y))), 0); };
    expected["albedo"] = [&](int x, int y) {
        glm::vec3 a(texel(albedo, kWidth, x, y));
        bool unlit = (infoFlags(texel(info, kWidth, x, y)) & kSurfaceUnlit) != 0u;
        return std::make_pair(to8bit(unlit ? a : glm::pow(glm::clamp(a, 0.0f, 1.0f), glm::vec3(1.0f / 2.2f))), 1);
    };
    expected["normal"] = [&](int x, int y) {
        glm::vec3 n(texel(normal, kWidth, x, y));
        return std::make_pair(to8bit(0.5f + 0.5f * glm::clamp(n, -1.0f, 1.0f)), 1);
    };
    expected["position"] = [&](int x, int y) {
        glm::vec4 p = texel(position, kWidth, x, y);
        if (p.w == 0.0f) return std::make_pair(glm::ivec3(0), 0);
        glm::vec3 v(p);
        glm::vec3 scaled = glm::sign(v) * glm::log(1.0f + glm::abs(v)) / std::log(1.0f + viewDistance);
        return std::make_pair(to8bit(0.5f + 0.5f * glm::clamp(scaled, -1.0f, 1.0f)), 1);
    };
    expected["info"] = [&](int x, int y) {
        glm::vec4 i = texel(info, kWidth, x, y);
        if (infoFlags(i) & kSurfaceSky) return std::make_pair(glm::ivec3(0, 0, 204), 0);
        return std::make_pair(to8bit({std::round(i.r * 255.0f) / 64.0f, i.g / 0.25f, 0.0f}), 1);
    };
    expected["depth"] = [&](int x, int y) {
        float d = depth[size_t(y) * kWidth + size_t(x)];
        if (d >= 1.0f) return std::make_pair(glm::ivec3(0), 0);
        float ndc = d * 2.0f - 1.0f;
        float eye = 2.0f * nearPlane * farPlane / (farPlane + nearPlane - ndc * (farPlane - nearPlane));
        return std::make_pair(to8bit(ramp(std::log(eye / nearPlane) / std::log(farPlane / nearPlane))), 1);
    };
    expected["stencil"] = [&](int x, int y) {
        uint8_t s = stencil[size_t(y) * kWidth + size_t(x)];
        if (s == 0) return std::make_pair(glm::ivec3(0), 0);
        EXPECT_EQ(s, 1) << "only terrain (1) writes stencil";
        return std::make_pair(glm::ivec3(242, 158, 31), 2);  // (0.95, 0.62, 0.12)
    };

    for (const DebugView& view : debugViews()) {
        ASSERT_TRUE(expected.count(view.name)) << "no semantic check for view " << view.name;
        int wrong = 0, black = 0;
        std::string first;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
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

    // The stencil view through stencil texturing equals the CPU read-back path bit for bit,
    // alone and inside the overview.
    for (const std::string& name : {std::string("stencil"), std::string(kOverviewName)}) {
        renderer.setStencilViewPath(StencilViewPath::Texturing);
        renderer.renderView(name);
        Image texturing = renderer.readDisplay();
        renderer.setStencilViewPath(StencilViewPath::ReadBack);
        renderer.renderView(name);
        Image readBack = renderer.readDisplay();
        EXPECT_TRUE(texturing.rgba == readBack.rgba) << name << ": stencil texturing and read-back differ (max "
                                                     << compareImages(texturing, readBack).maxAbs << ")";
        EXPECT_TRUE(hasContent(readBack)) << name;
    }
}

INSTANTIATE_TEST_SUITE_P(Layouts, DebugViewSemantics, ::testing::Values("full", "standard"),
                         [](const auto& info) { return info.param; });

// The overview: a grid of every view, one per tile, each labelled. Each tile is the view sampled
// at the tile's resolution (nearest), so every tile pixel outside the label must equal its view's
// pixel at the sampled texel (or a neighbour, for the rounding of the sample position).
TEST_F(DebugViews, OverviewTilesShowEveryViewWithLabels) {
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kWidth, kHeight, layoutNamed("standard"));
    renderer.setPipeline(PipelineKind::Deferred);
    renderer.renderFrame(pose.scene);
    std::vector<Image> views;
    for (const DebugView& view : debugViews()) {
        renderer.renderView(view.name);
        views.push_back(renderer.readDisplay());
    }
    renderer.renderView(kOverviewName);
    Image overview = renderer.readDisplay();
    dumpImage("overview", overview);
    std::vector<OverviewTile> tiles = overviewTiles(kWidth, kHeight);
    ASSERT_EQ(tiles.size(), views.size());

    for (size_t i = 0; i < tiles.size(); ++i) {
        const OverviewTile& tile = tiles[i];
        const std::string& name = debugViews()[i].name;
        SCOPED_TRACE("tile " + std::to_string(i) + " (" + name + ")");
        auto outsideLabel = [&](int x, int y) { return !inside(tile.label, x, y); };
        RgbStats stats = rgbStats(overview, tile.area, outsideLabel);
        EXPECT_TRUE(stats.distinctColours > 1 && stats.maxStddev() > kMinChannelStddev) << "flat tile: " << describe(stats);

        int tileWidth = tile.area.x1 - tile.area.x0, tileHeight = tile.area.y1 - tile.area.y0;
        int mismatches = 0;
        std::string first;
        for (int y = tile.area.y0; y < tile.area.y1; ++y) {
            for (int x = tile.area.x0; x < tile.area.x1; ++x) {
                if (!outsideLabel(x, y)) continue;
                // Source texel in GL (bottom-up) coordinates, then back to the top-down image.
                int localX = x - tile.area.x0, localYUp = tile.area.y1 - 1 - y;
                int sourceX = int(std::floor((localX + 0.5) / tileWidth * kWidth));
                int sourceYUp = int(std::floor((localYUp + 0.5) / tileHeight * kHeight));
                const uint8_t* got = overview.pixel(x, y);
                bool found = false;
                for (int dy = -1; dy <= 1 && !found; ++dy) {
                    for (int dx = -1; dx <= 1 && !found; ++dx) {
                        int sx = std::clamp(sourceX + dx, 0, kWidth - 1);
                        int sy = kHeight - 1 - std::clamp(sourceYUp + dy, 0, kHeight - 1);
                        const uint8_t* want = views[i].pixel(sx, sy);
                        found = std::abs(got[0] - want[0]) <= 1 && std::abs(got[1] - want[1]) <= 1 &&
                                std::abs(got[2] - want[2]) <= 1;
                    }
                }
                if (!found && mismatches++ == 0)
                    first = "(" + std::to_string(x) + ", " + std::to_string(y) + ") got " +
                            str({got[0], got[1], got[2]});
            }
        }
        EXPECT_EQ(mismatches, 0) << "tile pixels that are not the view's; first " << first;

        // The label: white text on a dark box in the tile's top-left corner.
        int white = 0;
        for (int y = tile.label.y0; y < tile.label.y1; ++y)
            for (int x = tile.label.x0; x < tile.label.x1; ++x) {
                const uint8_t* p = overview.pixel(x, y);
                if (p[0] >= 250 && p[1] >= 250 && p[2] >= 250) ++white;
            }
        EXPECT_GE(white, 10) << "no label text in the tile's corner";
    }
    // Tiles are different views, not one view repeated (compared below the labels' rows).
    for (size_t a = 0; a < tiles.size(); ++a)
        for (size_t b = a + 1; b < tiles.size(); ++b) {
            int differing = 0;
            for (int y = tiles[a].area.y0 + 30; y < tiles[a].area.y1; ++y)
                for (int x = tiles[a].area.x0; x < tiles[a].area.x1; ++x) {
                    int bx = x - tiles[a].area.x0 + tiles[b].area.x0, by = y - tiles[a].area.y0 + tiles[b].area.y0;
                    const uint8_t *p = overview.pixel(x, y), *q = overview.pixel(bx, by);
                    if (std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2]) > 6) ++differing;
                }
            EXPECT_GT(differing, 100) << "tiles " << a << " and " << b << " look the same";
        }
}

}  // namespace
}  // namespace oasis::gputest
