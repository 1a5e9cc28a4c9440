// Debug views: every view and the overview have content in both pipelines (forward's G-buffer
// views equal deferred's), the two stencil paths agree bit for bit, and every overview tile shows
// its view under its label (each view's colours against its remapping: debug_view_semantics_test.cpp).
#include "debug_views_support.h"
#include "render/plant_atlas.h"

namespace oasis::gputest {
namespace {



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
        // The tiles of the frame's surfaces name the water scene they show where it fits.
        size_t letters = overviewLabel(oasis::overviewTiles(width, height)[i], "direct").size();
        int labelWidth = int(std::ceil((8.0f * float(letters) + 10.0f) * scale)) + 4;
        int labelHeight = int(std::ceil(24.0f * scale)) + 4;
        tile.label = tileHeight >= 24 ? Region{x, y, std::min(x + labelWidth, x + tileWidth), std::min(y + labelHeight, y + tileHeight)}
                                      : Region{x, y, x, y};
        tiles.push_back(tile);
    }
    return tiles;
}
bool inside(const Region& r, int x, int y) { return x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1; }

class DebugViews : public GpuTest {};

// PSNR (8-bit RGB) of two images over a region, as compareImages computes it over a whole image.
double regionPsnr(const Image& a, const Image& b, const Region& r) {
    double sumSquares = 0.0;
    size_t count = 0;
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x)
            for (int c = 0; c < 3; ++c) {
                double d = double(a.pixel(x, y)[c]) - double(b.pixel(x, y)[c]);
                sumSquares += d * d;
                ++count;
            }
    if (count == 0 || sumSquares == 0.0) return kPsnrIdentical;
    return std::min(kPsnrIdentical, 10.0 * std::log10(255.0 * 255.0 / (sumSquares / double(count))));
}

// Pixels (top-down) where two images differ in any channel, split by a predicate on (x, y from bottom).
struct DifferingPixels {
    int where = 0, elsewhere = 0;
};
DifferingPixels differingPixels(const Image& a, const Image& b, const std::function<bool(int, int)>& split) {
    DifferingPixels result;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            int yUp = a.height - 1 - y;
            if (maxChannelDifference(displayPixel(a, x, yUp), displayPixel(b, x, yUp)) == 0) continue;
            (split(x, yUp) ? result.where : result.elsewhere)++;
        }
    return result;
}

// Every view and the overview show content in both pipelines. Forward draws no G-buffer, so its
// G-buffer views come from the deferred passes before the first that writes Radiance (the direct
// scene), which the renderer runs on demand: they must equal the deferred frame's views outside the
// water mask bit for bit, even when the G-buffer still holds another (deferred) frame. Inside the
// mask the deferred G-buffer holds the mirrored scene, so there forward shows what deferred shows
// with reflections off (the terrain under the water): equal to that frame's views everywhere.
// Depth and stencil views are the same in both pipelines; the lit views (final, reflection) agree
// by PSNR; the reflection view is black outside the water.
TEST_F(DebugViews, EveryViewHasContentInBothPipelinesAndForwardEqualsDeferred) {
    NamedPose pose = defaultPose();
    NamedPose other = poseNamed("sunset");
    SceneSettings noReflections = pose.scene;
    noReflections.water.reflections = false;
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("standard"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.setPipeline(PipelineKind::Deferred);
    renderer.renderFrame(pose.scene);
    const std::vector<uint8_t> stencil = readStencil(renderer);
    auto inWater = [&](int x, int yUp) { return stencil[size_t(yUp) * kMediumWidth + size_t(x)] == kStencilWater; };
    const int waterPixels = int(std::count(stencil.begin(), stencil.end(), kStencilWater));
    ASSERT_GT(waterPixels, kMediumWidth * kMediumHeight / 20) << "the default frame should show the lake";

    std::vector<OverviewTile> tiles = overviewTiles(kMediumWidth, kMediumHeight);
    for (const std::string& name : allViewNames()) {
        SCOPED_TRACE("view " + name);
        Image deferredOff = renderView(renderer, noReflections, PipelineKind::Deferred, name);
        Image deferred = renderView(renderer, pose.scene, PipelineKind::Deferred, name);
        renderer.renderFrame(other.scene);  // leave a different deferred frame in the G-buffer
        Image forward = renderView(renderer, pose.scene, PipelineKind::Forward, name);
        EXPECT_TRUE(readStencil(renderer) == stencil) << "forward stencil differs from deferred";
        dumpImage("view-" + name + "-deferred", deferred);
        dumpImage("view-" + name + "-forward", forward);
        EXPECT_TRUE(hasContent(deferred)) << "deferred";
        EXPECT_TRUE(hasContent(forward)) << "forward";

        ImageDifference difference = compareImages(deferred, forward);
        const DebugView* view = findDebugView(name);
        // The vegetation view shows lit pixels (Final), masked by the G-buffer's plant flags.
        if (name == "final" || name == "reflection" || name == "vegetation" || name == "radiance" ||
            name == "reflection-raw") {
            std::printf("[views] %s: forward vs deferred PSNR %.2f dB, max %d\n", name.c_str(), difference.psnrDb,
                        difference.maxAbs);
            EXPECT_GE(difference.psnrDb, 45.0) << name << " view: forward and deferred disagree";
            if (name == "reflection" || name == "reflection-raw") {
                DifferingPixels lit = differingPixels(deferred, Image(kMediumWidth, kMediumHeight), inWater);
                EXPECT_EQ(differingPixels(forward, Image(kMediumWidth, kMediumHeight), inWater).elsewhere, 0)
                    << "forward reflection view not black outside the water";
                EXPECT_EQ(lit.elsewhere, 0) << "deferred reflection view not black outside the water";
                EXPECT_GT(lit.where, waterPixels / 2) << "deferred reflection view mostly black in the water";
            }
        } else if (name == kOverviewName) {
            // Tiles of G-buffer views, depth and stencil: forward equals deferred without reflections
            // bit for bit; the lit tiles (final, reflection) agree with deferred by PSNR.
            for (size_t t = 0; t < tiles.size(); ++t) {
                const std::string& tileView = debugViews()[t].name;
                SCOPED_TRACE("tile " + tileView);
                if (tileView == "final" || tileView == "reflection" || tileView == "vegetation" ||
                    tileView == "radiance" || tileView == "reflection-raw") {
                    EXPECT_GE(regionPsnr(deferred, forward, tiles[t].area), 45.0);
                } else {
                    EXPECT_EQ(regionPsnr(deferredOff, forward, tiles[t].area), kPsnrIdentical)
                        << "forward tile differs from deferred without reflections";
                }
            }
        } else if (view && readsGBuffer(*view)) {
            // Both pipelines show the water scene asked for (frame/view_fill.h): the direct one by
            // default, as deferred without reflections shows it; the mirrored one differs from it in
            // the water only, and is the same in both pipelines too.
            EXPECT_EQ(difference.maxAbs, 0) << "forward and deferred show different " << name;
            EXPECT_EQ(compareImages(deferredOff, forward).maxAbs, 0)
                << "forward " << name << " differs from deferred with reflections off";
            renderer.views().setWaterScene(WaterScene::Mirrored);
            Image mirrored = renderView(renderer, pose.scene, PipelineKind::Deferred, name);
            Image mirroredForward = renderView(renderer, pose.scene, PipelineKind::Forward, name);
            renderer.views().setWaterScene(WaterScene::Direct);
            DifferingPixels versusDirect = differingPixels(mirrored, deferred, inWater);
            EXPECT_EQ(versusDirect.elsewhere, 0) << "the mirrored scene changed " << name << " outside the water";
            EXPECT_GT(versusDirect.where, 0) << "the mirrored scene shows the direct one in the water";
            EXPECT_EQ(compareImages(mirrored, mirroredForward).maxAbs, 0)
                << "forward and deferred show a different mirrored " << name;
        } else {
            EXPECT_EQ(difference.maxAbs, 0) << "forward and deferred show different " << name << " (PSNR "
                                            << difference.psnrDb << " dB)";
            EXPECT_EQ(compareImages(deferredOff, forward).maxAbs, 0) << name << " changed with reflections off";
        }
    }
}

// Filling the G-buffer for a view of a forward frame must not change the forward frame's picture
// or stencil; its depth changes only under the water, where the views show the lakebed's.
TEST_F(DebugViews, GBufferViewOfForwardFrameKeepsFinalDepthAndStencil) {
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("standard"));
    Image before = renderView(renderer, pose.scene, PipelineKind::Forward, "final");
    std::vector<float> depthBefore = readDepth(renderer);
    std::vector<uint8_t> stencilBefore = readStencil(renderer);
    ASSERT_TRUE(hasContent(before));
    renderer.views().render("albedo");
    ASSERT_TRUE(hasContent(readDisplay(renderer)));
    renderer.views().render("final");
    Image after = readDisplay(renderer);
    EXPECT_EQ(compareImages(before, after).maxAbs, 0) << "the forward frame's Final changed";
    EXPECT_TRUE(readStencil(renderer) == stencilBefore) << "the forward frame's stencil changed";
    const std::vector<float> depthAfter = readDepth(renderer);
    long changedOutsideWater = 0, changedInWater = 0;
    for (size_t i = 0; i < depthAfter.size(); ++i)
        if (depthAfter[i] != depthBefore[i]) ++(stencilBefore[i] == kStencilWater ? changedInWater : changedOutsideWater);
    EXPECT_EQ(changedOutsideWater, 0) << "the forward frame's depth changed outside the water";
    EXPECT_GT(changedInWater, 0) << "the depth under the water is not the lakebed's";
}

// The same for a forward frame stopped before a pass (renderFrame's stopBefore, the CLI's
// --stop-before): the fill runs the deferred geometry passes up to the water mask whatever the
// forward frame reached, so it must not leave their depth and stencil behind. Stopped before
// WaterMaskPass the frame has no water in its stencil; stopped before its TerrainPass, no depth.
TEST_F(DebugViews, GBufferViewOfStoppedForwardFrameKeepsDepthAndStencil) {
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("standard"));
    renderer.setPipeline(PipelineKind::Forward);
    for (const std::string& stop : {std::string("WaterMaskPass"), std::string("TerrainPass.forward")}) {
        SCOPED_TRACE("forward frame stopped before " + stop);
        renderer.renderFrame(pose.scene, stop);
        std::vector<float> depthBefore = readDepth(renderer);
        std::vector<uint8_t> stencilBefore = readStencil(renderer);
        EXPECT_EQ(std::count(stencilBefore.begin(), stencilBefore.end(), kStencilWater), 0);
        renderer.views().render("albedo");
        std::vector<float> depthAfter = readDepth(renderer);
        std::vector<uint8_t> stencilAfter = readStencil(renderer);
        size_t depthChanged = 0, stencilChanged = 0;
        for (size_t i = 0; i < depthBefore.size(); ++i) {
            depthChanged += depthBefore[i] != depthAfter[i] ? 1 : 0;
            stencilChanged += stencilBefore[i] != stencilAfter[i] ? 1 : 0;
        }
        EXPECT_EQ(depthChanged, 0u) << "a G-buffer view changed the stopped forward frame's depth";
        EXPECT_EQ(stencilChanged, 0u) << "a G-buffer view changed the stopped forward frame's stencil (the stencil "
                                         "view now shows passes the frame never ran)";
    }
}


// The overview: a grid of every view, one per tile, each labelled. Each tile is the view sampled
// at the tile's resolution (nearest), so every tile pixel outside the label must equal its view's
// pixel at the sampled texel (or a neighbour, for the rounding of the sample position).
TEST_F(DebugViews, OverviewTilesShowEveryViewWithLabels) {
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("standard"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.setPipeline(PipelineKind::Deferred);
    renderer.renderFrame(pose.scene);
    // What each tile samples: the view at frame size, except the atlas view, which samples the atlas.
    std::vector<Image> views;
    for (const DebugView& view : debugViews()) {
        renderer.views().render(view.name);
        views.push_back(view.source == ViewSource::PlantAtlas ? atlas->read() : readDisplay(renderer));
    }
    renderer.views().render(kOverviewName);
    Image overview = readDisplay(renderer);
    dumpImage("overview", overview);
    std::vector<OverviewTile> tiles = overviewTiles(kMediumWidth, kMediumHeight);
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
                const int sourceWidth = views[i].width, sourceHeight = views[i].height;
                int sourceX = int(std::floor((localX + 0.5) / tileWidth * sourceWidth));
                int sourceYUp = int(std::floor((localYUp + 0.5) / tileHeight * sourceHeight));
                const uint8_t* got = overview.pixel(x, y);
                bool found = false;
                for (int dy = -1; dy <= 1 && !found; ++dy) {
                    for (int dx = -1; dx <= 1 && !found; ++dx) {
                        int sx = std::clamp(sourceX + dx, 0, sourceWidth - 1);
                        int sy = sourceHeight - 1 - std::clamp(sourceYUp + dy, 0, sourceHeight - 1);
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
