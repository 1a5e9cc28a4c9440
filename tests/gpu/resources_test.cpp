// GL resources: 100 pipeline switches and 20 size/layout round trips leave both the wrappers' live
// object counts and an independent glIs* probe of the driver's names unchanged (no leaked GL objects).
#include "frame/frame_readback.h"
#include "gpu_test.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <unistd.h>

#include "gl_objects_probe.h"

namespace oasis::gputest {
namespace {

class Resources : public GpuTest {
protected:
    // Everything that creates objects lazily: both pipelines, every view, both stencil paths, overview.
    void exerciseEverything(Renderer& renderer, const SceneSettings& scene) {
        for (PipelineKind kind : {PipelineKind::Deferred, PipelineKind::Forward}) {
            renderer.setPipeline(kind);
            renderer.renderFrame(scene);
            for (const DebugView& view : debugViews()) renderer.views().render(view.name);
            for (StencilViewPath path : {StencilViewPath::ReadBack, StencilViewPath::Texturing}) {
                renderer.views().setStencilPath(path);
                renderer.views().render("stencil");
                renderer.views().render(kOverviewName);
            }
        }
        glFinish();
    }
};

TEST_F(Resources, HundredPipelineSwitchesLeakNothing) {
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    // 128x96: the overview's 4x4 tiles are 24 px high, the smallest that gets labels (ImGui's objects).
    renderer.configure(128, 96, layoutNamed("standard"));
    exerciseEverything(renderer, pose.scene);  // warm-up: programs, label overlay, stencil copy exist
    const LiveCounts countsBefore = liveCounts();
    const GlNameProbe probeBefore = probeNames();
    std::cout << "[resources] live " << countsBefore << ", probe " << probeBefore << "\n";
    ASSERT_GT(countsBefore.total, 10);
    ASSERT_GT(probeBefore.textures, 5) << probeBefore;
    ASSERT_GT(probeBefore.programs, countsBefore.byKind[size_t(gl::ObjectKind::Program)])
        << "the label overlay's own program should be live: " << probeBefore;

    Image lastImage;
    for (int i = 0; i < 100; ++i) {
        PipelineKind kind = i % 2 ? PipelineKind::Forward : PipelineKind::Deferred;
        renderer.setPipeline(kind);
        ASSERT_EQ(renderer.pipeline(), kind);
        renderer.renderFrame(pose.scene);
        renderer.views().render(i % 4 < 2 ? "final" : (i % 4 == 2 ? "normal" : kOverviewName));
        if (i == 99) lastImage = readDisplay(renderer);
    }
    glFinish();
    EXPECT_EQ(liveCounts(), countsBefore) << "wrapper live object counts changed over 100 pipeline switches";
    EXPECT_EQ(probeNames(), probeBefore) << "glIs* probe changed over 100 pipeline switches";
    EXPECT_TRUE(hasContent(lastImage)) << "the last frame rendered nothing";
}

TEST_F(Resources, TwentySizeAndLayoutRoundTripsLeakNothing) {
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(128, 72, layoutNamed("full"));
    exerciseEverything(renderer, pose.scene);
    renderer.configure(64, 36, layoutNamed("standard"));
    exerciseEverything(renderer, pose.scene);
    const LiveCounts countsBefore = liveCounts();
    const GlNameProbe probeBefore = probeNames();

    for (int i = 0; i < 20; ++i) {
        renderer.configure(128, 72, layoutNamed("full"));
        ASSERT_EQ(renderer.targets().width(), 128);
        ASSERT_EQ(renderer.targets().layout().name, "full");  // configure() keeps a copy of the layout
        renderer.setPipeline(i % 2 ? PipelineKind::Forward : PipelineKind::Deferred);
        renderer.renderFrame(pose.scene);
        renderer.views().setStencilPath(StencilViewPath::ReadBack);  // re-creates its copy at each size
        renderer.views().render("stencil");
        renderer.views().render("position");
        renderer.configure(64, 36, layoutNamed("standard"));
        ASSERT_EQ(renderer.targets().height(), 36);
        renderer.renderFrame(pose.scene);
        renderer.views().render(kOverviewName);
        renderer.views().setStencilPath(StencilViewPath::Texturing);
        renderer.views().render("stencil");
    }
    glFinish();
    EXPECT_EQ(liveCounts(), countsBefore) << "wrapper live object counts changed over 20 reconfigure round trips";
    EXPECT_EQ(probeNames(), probeBefore) << "glIs* probe changed over 20 reconfigure round trips";

    // The renderer still renders correctly at the size it ended on.
    renderer.setPipeline(PipelineKind::Deferred);
    Image image = renderFinal(renderer, pose.scene, PipelineKind::Deferred);
    EXPECT_EQ(image.width, 64);
    EXPECT_TRUE(hasContent(image));
}

// A frame whose scene asks for another terrain grid density rebuilds the grid (what `oasis bench`'s
// grid knob relies on), draws with it, and round trips leave no GL objects behind.
TEST_F(Resources, GridDensityChangesRebuildTheGridAndLeakNothing) {
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(64, 36, layoutNamed("standard"));
    SceneSettings coarse = pose.scene;
    coarse.grid.rings = 40;
    coarse.grid.segments = 32;
    const int defaultTriangles = int(buildTerrainGrid(pose.scene.grid).indices.size() / 3);
    const int coarseTriangles = int(buildTerrainGrid(coarse.grid).indices.size() / 3);
    ASSERT_NE(defaultTriangles, coarseTriangles);
    renderFinal(renderer, pose.scene, PipelineKind::Deferred);  // builds the final view's program too
    EXPECT_EQ(renderer.parts().geometry.terrainTriangles(), defaultTriangles);
    const LiveCounts countsBefore = liveCounts();
    for (int i = 0; i < 5; ++i) {
        Image image = renderFinal(renderer, coarse, PipelineKind::Deferred);
        EXPECT_EQ(renderer.parts().geometry.terrainTriangles(), coarseTriangles);
        EXPECT_TRUE(hasContent(image));
        renderer.renderFrame(pose.scene);
        EXPECT_EQ(renderer.parts().geometry.terrainTriangles(), defaultTriangles);
    }
    glFinish();
    EXPECT_EQ(liveCounts(), countsBefore) << "wrapper live object counts changed over grid density round trips";
}

// A renderer that is destroyed gives back everything it made, its label overlay (ImGui) included;
// the shader library keeps its programs.
TEST_F(Resources, DestroyedRendererReleasesItsObjects) {
    NamedPose pose = defaultPose();
    {
        Renderer warm(*shaders_, pose.scene);
        warm.configure(128, 72, layoutNamed("standard"));
        exerciseEverything(warm, pose.scene);  // compile every program the renderer uses
    }
    const LiveCounts countsBefore = liveCounts();
    const GlNameProbe probeBefore = probeNames();
    {
        Renderer renderer(*shaders_, pose.scene);
        renderer.configure(128, 72, layoutNamed("full"));
        exerciseEverything(renderer, pose.scene);
        EXPECT_GT(liveCounts().total, countsBefore.total);
    }
    glFinish();
    EXPECT_EQ(liveCounts(), countsBefore);
    EXPECT_EQ(probeNames(), probeBefore);
}

// A pipeline switch whose programs were never built and do not build now (terrain.frag broken on
// disk in its forward variants only: the deferred pipeline draws the sky with sky.frag too)
// throws ShaderBuildError naming file:line, leaves no GL object behind, and the pipeline that drew
// before draws the same image after; once the file is mended the switch works (what the window's
// undo of a failed switch relies on).
TEST_F(Resources, FailedProgramBuildIsRecoverable) {
    namespace fs = std::filesystem;
    const fs::path copy = fs::temp_directory_path() / ("oasis-resources-shaders-" + std::to_string(::getpid()));
    fs::remove_all(copy);
    fs::copy(shaderDir_, copy, fs::copy_options::recursive);
    const fs::path terrain = copy / "terrain.frag";
    std::string original;
    {
        std::ifstream in(terrain);
        original.assign(std::istreambuf_iterator<char>(in), {});
    }
    const int brokenLine = int(std::count(original.begin(), original.end(), '\n')) + 2;
    std::ofstream(terrain, std::ios::app) << "#if defined(OUTPUT_FORWARD)\nthis is not GLSL;\n#endif\n";

    ShaderLibrary library(copy.string(), glslDialectForCurrentContext());
    NamedPose pose = defaultPose();
    Renderer renderer(library, pose.scene);
    renderer.configure(64, 36, layoutNamed("compact"));
    const Image before = renderFinal(renderer, pose.scene, PipelineKind::Deferred);
    ASSERT_TRUE(hasContent(before));
    const LiveCounts countsBefore = liveCounts();
    const size_t programsBefore = library.programCount();

    renderer.setPipeline(PipelineKind::Forward);
    try {
        renderer.renderFrame(pose.scene);
        ADD_FAILURE() << "a forward frame with a broken terrain.frag did not throw";
    } catch (const ShaderBuildError& error) {
        EXPECT_NE(std::string(error.what()).find("terrain.frag:" + std::to_string(brokenLine)), std::string::npos)
            << error.what();
    }
    glFinish();
    // The forward programs that built before terrain.frag's failed stay in the library; nothing else is new.
    LiveCounts expected = countsBefore;
    const int built = int(library.programCount() - programsBefore);
    expected.byKind[size_t(gl::ObjectKind::Program)] += built;
    expected.total += built;
    EXPECT_EQ(liveCounts(), expected) << "the failed build left objects behind";
    const Image after = renderFinal(renderer, pose.scene, PipelineKind::Deferred);
    EXPECT_EQ(compareImages(before, after).maxAbs, 0) << "the deferred frame changed after the failed switch";

    std::ofstream(terrain, std::ios::trunc) << original;
    EXPECT_TRUE(hasContent(renderFinal(renderer, pose.scene, PipelineKind::Forward)));
    std::error_code ignored;
    fs::remove_all(copy, ignored);
}

}  // namespace
}  // namespace oasis::gputest
