// The frame graph from the passes' declarations, without GL: which passes it culls and why, and
// that a read with no writer before it is reported (frame/frame_graph.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "frame/frame_graph.h"
#include "frame/pipeline.h"
#include "frame/view_fill.h"

namespace oasis {
namespace {

const GraphStep& stepNamed(const FrameGraph& graph, const std::string& name) {
    auto found = std::find_if(graph.steps.begin(), graph.steps.end(),
                              [&](const GraphStep& step) { return step.pass->name() == name; });
    if (found == graph.steps.end()) throw std::out_of_range("no step " + name);
    return *found;
}

// A compact frame with reflections and point lights added by `method`.
FrameSetup compactFrame(LightMethod method, bool depthReadInPlace) {
    FrameSetup frame;
    frame.positionFromDepth = true;
    frame.work.depthReadInPlace = depthReadInPlace;
    frame.lightMethod = method;
    frame.lights.resize(2);
    return frame;
}

TEST(FrameGraph, TheDepthCopyRunsOnlyWhereAPassReadsIt) {
    Pipeline deferred(PipelineKind::Deferred);
    FrameGraph tiled = deferred.graph(compactFrame(LightMethod::Tiled, true));
    EXPECT_FALSE(stepNamed(tiled, "DepthCopyPass").runs);
    EXPECT_EQ(stepNamed(tiled, "DepthCopyPass").culled, "nothing later reads what it writes (scene-depth)");
    EXPECT_TRUE(stepNamed(tiled, "DepthCopyPass.mirrored").runs) << "the mirrored lighting reads the copy";
    EXPECT_TRUE(stepNamed(deferred.graph(compactFrame(LightMethod::Volumes, true)), "DepthCopyPass").runs)
        << "the light volumes read the copy";
    EXPECT_TRUE(stepNamed(deferred.graph(compactFrame(LightMethod::Tiled, false)), "DepthCopyPass").runs)
        << "the lighting reads the copy with --depth-read copy";
    FrameSetup full = compactFrame(LightMethod::Volumes, true);
    full.positionFromDepth = false;
    EXPECT_EQ(stepNamed(deferred.graph(full), "DepthCopyPass").culled, "off in this frame's settings");
}

TEST(FrameGraph, TheLightTilesAreBuiltOnlyForTheTiledLighting) {
    Pipeline deferred(PipelineKind::Deferred);
    EXPECT_TRUE(stepNamed(deferred.graph(compactFrame(LightMethod::Tiled, true)), "LightTilingPass").runs);
    FrameGraph volumesGraph = deferred.graph(compactFrame(LightMethod::Volumes, true));
    const GraphStep& volumes = stepNamed(volumesGraph, "LightTilingPass");
    EXPECT_FALSE(volumes.runs);
    EXPECT_EQ(volumes.culled, "nothing later reads what it writes (LightTiles)");
    FrameSetup noLights = compactFrame(LightMethod::Tiled, true);
    noLights.lights.clear();
    EXPECT_FALSE(stepNamed(deferred.graph(noLights), "LightTilingPass").runs);
}

TEST(FrameGraph, TheCompactLayoutDeclaresNoPosition) {
    Pipeline deferred(PipelineKind::Deferred);
    FrameGraph graph = deferred.graph(compactFrame(LightMethod::Volumes, true));
    for (const GraphStep& step : graph.steps) {
        EXPECT_EQ(std::count(step.reads.begin(), step.reads.end(), Resource(Target::Position)), 0) << step.pass->name();
        EXPECT_EQ(std::count(step.writes.begin(), step.writes.end(), Resource(Target::Position)), 0) << step.pass->name();
    }
}

TEST(FrameGraph, EveryReadOfBothPipelinesHasAWriterBeforeIt) {
    for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
        Pipeline pipeline(kind);
        for (LightMethod method : {LightMethod::Volumes, LightMethod::Tiled})
            for (bool inPlace : {true, false})
                for (bool reflections : {true, false})
                    for (bool shadows : {true, false}) {
                        FrameSetup frame = compactFrame(method, inPlace);
                        frame.reflectionsActive = reflections;
                        frame.shadowsActive = shadows;
                        FrameGraph graph = pipeline.graph(frame);
                        EXPECT_TRUE(graph.problems.empty()) << pipelineName(kind) << ": " << graph.problems.front();
                    }
    }
}

// A view's frame is one graph (Renderer::requestGraph): the frame's passes, then the views' fill
// after it, culled from what the albedo view reads. The fill clears the depth-stencil whole
// (ClearPass's Replace) and draws the G-buffer over what the frame left, so the frame runs the
// geometry and none of the shading.
TEST(FrameGraph, AViewOfTheGBufferCullsTheShading) {
    FrameSetup frame = compactFrame(LightMethod::Tiled, true);
    frame.reflectionsActive = true;
    ViewFill fill;
    Pipeline deferred(PipelineKind::Deferred);
    std::vector<GraphStep> steps;
    for (const auto& pass : deferred.passes()) steps.push_back(graphStep(*pass, frame));
    for (const Pass* pass : fill.passes(WaterScene::Direct, frame)) steps.push_back(graphStep(*pass, frame, true));
    FrameGraph graph = buildFrameGraph(steps, frame, {Target::Albedo, Target::Normal, Target::Info, Target::DepthStencil},
                                       frameInputs());
    graph.steps.resize(deferred.passes().size());  // the frame's steps
    for (const char* runs : {"ClearPass.gbuffer", "TerrainPass.gbuffer", "VegetationPass.gbuffer",
                             "TerrainPass.gbuffer.mirrored"})
        EXPECT_TRUE(stepNamed(graph, runs).runs) << runs;
    for (const char* culled : {"LightingPass", "SkyPass.deferred", "LightingPass.mirrored", "WaterCompositePass",
                               "LightTilingPass", "DepthCopyPass.mirrored"})
        EXPECT_FALSE(stepNamed(graph, culled).runs) << culled;
    EXPECT_EQ(stepNamed(graph, "LightingPass").culled, "nothing later reads what it writes (radiance)");
    EXPECT_TRUE(graph.problems.empty());
    // Nothing a pass of the frame writes reaches the depth view: the fill draws all of its depth
    // (from the plants' instances the renderer uploaded).
    steps.resize(deferred.passes().size());
    for (const Pass* pass : fill.passes(WaterScene::Mirrored, frame)) steps.push_back(graphStep(*pass, frame, true));
    FrameGraph depth = buildFrameGraph(steps, frame, {Target::DepthStencil}, frameInputs());
    for (const GraphStep& step : depth.steps)
        EXPECT_TRUE(step.afterFrame || !step.runs) << step.pass->name() << " runs for the depth view";
    EXPECT_TRUE(depth.problems.empty());
}

// A reader besides the views (the check's shading oracle, FrameViews::setSink's reads) reads the
// frame as it leaves it, before the views' fill: its reads are live after the frame's last step
// (GraphStep::readAfter), so their writers run though the view (depth) needs none of the frame.
TEST(FrameGraph, WhatIsReadAfterTheFrameKeepsItsWriters) {
    FrameSetup frame = compactFrame(LightMethod::Tiled, true);
    ViewFill fill;
    Pipeline deferred(PipelineKind::Deferred);
    std::vector<GraphStep> steps;
    for (const auto& pass : deferred.passes()) steps.push_back(graphStep(*pass, frame));
    steps.back().readAfter = {Target::Radiance};
    for (const Pass* pass : fill.passes(WaterScene::Direct, frame)) steps.push_back(graphStep(*pass, frame, true));
    FrameGraph graph = buildFrameGraph(steps, frame, {Target::DepthStencil}, frameInputs());
    EXPECT_TRUE(stepNamed(graph, "LightingPass").runs);
    EXPECT_TRUE(stepNamed(graph, "TerrainPass.gbuffer").runs) << "the lighting reads the frame's own G-buffer";
    EXPECT_TRUE(graph.problems.empty());
}

// The buffers are resources like the targets: the light list and the plants' instances are the
// frame's inputs (uploaded before the first pass), the tile lists LightTilingPass's; the printed
// graph lists each with its writers and readers.
TEST(FrameGraph, TheBuffersAreResourcesWithWritersAndReaders) {
    Pipeline deferred(PipelineKind::Deferred);
    FrameSetup frame = compactFrame(LightMethod::Tiled, true);
    frame.vegetationEnabled = true;
    frame.reflectionsActive = false;
    FrameGraph graph = deferred.graph(frame);
    EXPECT_TRUE(graph.problems.empty());
    const GraphStep& tiling = stepNamed(graph, "LightTilingPass");
    EXPECT_EQ(std::count(tiling.reads.begin(), tiling.reads.end(), Resource(Buffer::LightList)), 1);
    EXPECT_EQ(std::count(tiling.writes.begin(), tiling.writes.end(), Resource(Buffer::LightTiles)), 1);
    const GraphStep& plants = stepNamed(graph, "VegetationPass.gbuffer");
    EXPECT_EQ(std::count(plants.reads.begin(), plants.reads.end(), Resource(Buffer::PlantInstances)), 1);
    std::string text = frameGraphText(graph);
    EXPECT_NE(text.find("\n# LightTiles      LightTilingPass -> LightingPass\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\n# LightList       (before the passes) -> LightTilingPass, LightingPass\n"), std::string::npos)
        << text;
    EXPECT_NE(text.find("\n# PlantInstances  (before the passes) -> VegetationPass.gbuffer\n"), std::string::npos) << text;
    // Without the inputs the same reads have no writer.
    std::vector<const Pass*> passes;
    for (const auto& pass : deferred.passes()) passes.push_back(pass.get());
    FrameGraph noInputs = buildFrameGraph(passes, frame, frameOutputs());
    ASSERT_FALSE(noInputs.problems.empty());
    EXPECT_EQ(noInputs.problems.front(), "VegetationPass.gbuffer reads PlantInstances, which no pass wrote before it");
}

// A pass that samples the depth copy with nothing before it to make it.
class ReadsTheCopy : public Pass {
public:
    std::string name() const override { return "ReadsTheCopy"; }
    std::vector<Access> declaredAccesses(const FrameSetup&) const override {
        return {{Target::SceneDepth, Use::Sample}, {Target::Radiance, Use::Write}};
    }

protected:
    void execute(PassContext&) override {}
};

TEST(FrameGraph, AReadWithNoWriterIsReported) {
    ReadsTheCopy pass;
    FrameGraph graph = buildFrameGraph({&pass}, FrameSetup{}, frameOutputs());
    ASSERT_EQ(graph.problems.size(), 1u);
    EXPECT_EQ(graph.problems[0], "ReadsTheCopy reads scene-depth, which no pass wrote before it");
    EXPECT_TRUE(buildFrameGraph({&pass}, FrameSetup{}, frameOutputs(), everyResource()).problems.empty());
}

}  // namespace
}  // namespace oasis
