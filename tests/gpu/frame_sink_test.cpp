// A frame built for the view asked for (FrameViews::setSink, issue 30 item 1): it runs only
// the passes whose writes reach what the view reads (the views table's `reads`, walked back through
// the views' fill and the composite onto Radiance), and every view's picture and values are then the
// same, bit for bit, as after a whole frame: a read missing from the table would cull its writer
// and change the picture.
#include "debug_views_support.h"

#include <algorithm>
#include <stdexcept>

#include "frame/frame_readback.h"
#include "frame/frame_traffic.h"

namespace oasis::gputest {
namespace {


// Water, terrain, plants and sky from the lake's shore; `night`: 21:00 with four point lights
// added by volumes (LightVolumePass, the separate ToneMapPass), else 10:00 with the tone map fused.
SceneSettings lakeScene(bool night) {
    SceneSettings scene = sceneAtHeight(435.0, 4.0, 140.0, 30.0f, -3.0f);
    if (night) {
        scene.hour = 21.0;
        scene.lights.count = 4;
        scene.lights.method = LightMethod::Volumes;
    }
    return scene;
}

class FrameSink : public GpuTest {
protected:
    // The view drawn after a frame built for `sink` (empty: the whole frame); its values too.
    struct Shown {
        Image image;
        std::vector<float> values;
    };
    Shown show(Renderer& renderer, const SceneSettings& scene, const std::string& view,
               const std::vector<std::string>& sink) {
        renderer.views().setSink(sink);
        renderer.renderFrame(scene);
        renderer.views().render(view);
        Shown shown{readDisplay(renderer), {}};
        if (view != kOverviewName) shown.values = renderer.views().readValues(view);
        return shown;
    }
};

// The passes that ran for each view's sink, and the view's picture and values against a whole
// frame's, in both pipelines, a layout that rebuilds position from depth and one that stores it,
// day (fused tone map) and night (light volumes), the views' direct and mirrored water scenes.
TEST_F(FrameSink, EveryViewIsTheSameAfterItsOwnFrameAsAfterAWholeFrame) {
    struct Case {
        const char* layout;
        bool night;
        WaterScene water;
    };
    for (const Case& c : {Case{"compact", false, WaterScene::Direct}, Case{"compact", true, WaterScene::Direct},
                          Case{"standard", false, WaterScene::Direct}, Case{"compact", false, WaterScene::Mirrored}}) {
        const SceneSettings scene = lakeScene(c.night);
        SceneSettings decoy = sceneAtHeight(580.0, 12.0, 120.0, -80.0f, -4.0f);
        decoy.hour = c.night ? 20.0 : 17.5;
        decoy.lights = scene.lights;
        Renderer renderer(*shaders_, scene);
        auto atlas = attachPlantAtlas(*shaders_, renderer);
        renderer.configure(kTinyWidth, kTinyHeight, layoutNamed(c.layout));
        renderer.views().setWaterScene(c.water);
        for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
            renderer.setPipeline(kind);
            for (const std::string& view : allViewNames()) {
                SCOPED_TRACE(std::string(c.layout) + (c.night ? " night " : " day ") + waterSceneName(c.water) + " " +
                             pipelineName(kind) + " " + view);
                // Another place and hour first: what a culled pass should have written is then
                // wrong in the targets, not the same frame's.
                show(renderer, decoy, kOverviewName, {});
                const Shown own = show(renderer, scene, view, {view});
                const Shown whole = show(renderer, scene, view, {});
                ASSERT_EQ(whole.image.rgba.size(), own.image.rgba.size());
                EXPECT_TRUE(whole.image.rgba == own.image.rgba)
                    << "the view's own frame culled a pass it reads: max abs "
                    << compareImages(whole.image, own.image).maxAbs;
                EXPECT_TRUE(whole.values == own.values) << "the view's values differ after its own frame";
            }
        }
    }
}

// The frame's passes that ran (not the views' steps after it).
std::vector<std::string> passesRun(const FrameGraph& graph) {
    std::vector<std::string> names;
    for (const GraphStep& step : graph.steps)
        if (step.runs && !step.afterFrame) names.push_back(step.pass->name());
    return names;
}

std::string joinedNames(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : " ") + name;
    return text;
}

bool has(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

// Which passes each view's frame runs: the G-buffer views no shading, the depth, stencil and
// atlas views nothing of the frame (the views' fill draws what they show), the final view the
// whole frame's shading, the radiance view not the tone map.
TEST_F(FrameSink, EachViewRunsThePassesItsReadsNeed) {
    const std::vector<std::string> shading = {"LightingPass", "SkyPass.deferred", "LightingPass.mirrored",
                                              "SkyPass.deferred.mirrored", "WaterCompositePass", "ToneMapPass",
                                              "LightVolumePass", "LightVolumePass.mirrored"};
    for (bool night : {false, true}) {
        SCOPED_TRACE(night ? "night, light volumes" : "day, tone map fused");
        const SceneSettings scene = lakeScene(night);
        Renderer renderer(*shaders_, scene);
        auto atlas = attachPlantAtlas(*shaders_, renderer);
        renderer.configure(kTinyWidth, kTinyHeight, layoutNamed("compact"));
        auto runsFor = [&](PipelineKind kind, const std::string& view) {
            renderer.setPipeline(kind);
            renderer.views().setSink(view.empty() ? std::vector<std::string>{} : std::vector<std::string>{view});
            renderer.renderFrame(scene);
            std::vector<std::string> ran = passesRun(renderer.lastFrame().graph());
            std::printf("[ sink ] %s %s %s: %s\n", night ? "night" : "day", pipelineName(kind),
                        view.empty() ? "(whole frame)" : view.c_str(), joinedNames(ran).c_str());
            return ran;
        };
        const std::vector<std::string> whole = runsFor(PipelineKind::Deferred, "");
        for (const char* view : {"albedo", "normal", "position", "info", "light-volumes", "shadow"}) {
            std::vector<std::string> ran = runsFor(PipelineKind::Deferred, view);
            EXPECT_TRUE(has(ran, "TerrainPass.gbuffer")) << view;
            for (const std::string& pass : {"LightingPass", "SkyPass.deferred", "LightingPass.mirrored",
                                            "SkyPass.deferred.mirrored", "WaterCompositePass", "ToneMapPass"})
                EXPECT_FALSE(has(ran, pass)) << view << " runs " << pass;
            EXPECT_EQ(has(ran, "ShadowPass"), std::string(view) == "shadow" && has(whole, "ShadowPass")) << view;
        }
        for (const char* view : {"depth", "stencil", "atlas"}) {
            EXPECT_TRUE(runsFor(PipelineKind::Deferred, view).empty()) << view;
            EXPECT_TRUE(runsFor(PipelineKind::Forward, view).empty()) << view;
        }
        EXPECT_TRUE(runsFor(PipelineKind::Forward, "albedo").empty()) << "forward draws no G-buffer: the fill does";
        const std::vector<std::string> final = runsFor(PipelineKind::Deferred, "final");
        for (const std::string& pass : {"LightingPass", "SkyPass.deferred", "LightingPass.mirrored", "WaterCompositePass"})
            EXPECT_TRUE(has(final, pass)) << pass;
        EXPECT_EQ(has(final, "ToneMapPass"), night) << "the separate tone map only with the light volumes";
        EXPECT_EQ(final, whole) << "every pass of the whole frame reaches Final here";
        const std::vector<std::string> radiance = runsFor(PipelineKind::Deferred, "radiance");
        EXPECT_TRUE(has(radiance, "LightingPass"));
        EXPECT_FALSE(has(radiance, "ToneMapPass"));
        // The culled passes say why.
        renderer.views().setSink({"albedo"});
        renderer.setPipeline(PipelineKind::Deferred);
        renderer.renderFrame(scene);
        for (const GraphStep& step : renderer.lastFrame().graph().steps)
            if (step.pass->name() == "LightingPass")
                EXPECT_EQ(step.culled.rfind("nothing later reads what it writes (radiance", 0), 0u) << step.culled;
    }
}

// A frame built for one view shows no other: asking for one throws rather than showing targets
// the frame did not draw.
TEST_F(FrameSink, AViewTheFrameWasNotBuiltForIsRefused) {
    const SceneSettings scene = lakeScene(false);
    Renderer renderer(*shaders_, scene);
    renderer.configure(kTinyWidth, kTinyHeight, layoutNamed("compact"));
    renderer.views().setSink({"albedo"});
    renderer.renderFrame(scene);
    EXPECT_NO_THROW(renderer.views().render("albedo"));
    EXPECT_THROW(renderer.views().render("final"), std::logic_error);
    EXPECT_THROW(renderer.views().readValues("radiance"), std::logic_error);
    EXPECT_THROW(renderer.views().setSink({"no-such-view"}), std::invalid_argument);
    renderer.views().setSink({});
    renderer.renderFrame(scene);
    EXPECT_NO_THROW(renderer.views().render("final"));
}

// One graph per request (issue 43 item 3): after the frame's passes, the passes the views named
// need, as steps of the same graph ending in the displayed image: the composite onto Radiance (a
// fused frame's radiance view), the views' fill (a view of the surfaces), one pass per view; each
// reads what its view reads, has a writer before it (no problems), and is what draws the view.
TEST_F(FrameSink, TheViewsPassesAreStepsOfTheFramesGraph) {
    const SceneSettings scene = lakeScene(false);
    Renderer renderer(*shaders_, scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(kTinyWidth, kTinyHeight, layoutNamed("standard"));
    auto viewSteps = [&](PipelineKind kind, const std::vector<std::string>& sink) {
        renderer.setPipeline(kind);
        renderer.views().setSink(sink);
        renderer.renderFrame(scene);
        const FrameGraph& graph = renderer.lastFrame().graph();
        EXPECT_TRUE(graph.problems.empty()) << graph.problems.front();
        std::vector<std::string> names;
        bool views = false;
        for (const GraphStep& step : graph.steps) {
            EXPECT_TRUE(!views || step.afterFrame) << "the views' steps come after the frame's";
            views = views || step.afterFrame;
            if (step.afterFrame && step.runs) names.push_back(step.pass->name());
        }
        for (const std::string& view : sink) EXPECT_NO_THROW(renderer.views().render(view)) << view;
        return names;
    };
    auto readsOf = [&](const std::string& passName) {
        for (const GraphStep& step : renderer.lastFrame().graph().steps)
            if (step.pass->name() == passName && step.afterFrame) return step.reads;
        return std::vector<Resource>{};
    };
    auto has = [](const std::vector<Resource>& list, Resource resource) {
        return std::find(list.begin(), list.end(), resource) != list.end();
    };
    EXPECT_EQ(viewSteps(PipelineKind::Deferred, {"final"}), std::vector<std::string>{"DebugViewPass.final"});
    EXPECT_EQ(readsOf("DebugViewPass.final"), std::vector<Resource>{Target::Final});
    EXPECT_EQ(viewSteps(PipelineKind::Deferred, {"radiance"}),
              (std::vector<std::string>{"WaterCompositePass.radiance", "DebugViewPass.radiance"}));
    EXPECT_TRUE(has(readsOf("WaterCompositePass.radiance"), Target::Reflection));
    std::vector<std::string> albedo = viewSteps(PipelineKind::Forward, {"albedo"});
    ASSERT_FALSE(albedo.empty());
    EXPECT_EQ(albedo.back(), "DebugViewPass.albedo");
    EXPECT_TRUE(std::find(albedo.begin(), albedo.end(), "TerrainPass.gbuffer") != albedo.end())
        << "a forward frame's albedo view: the views' fill draws the surfaces";
    EXPECT_TRUE(has(readsOf("DebugViewPass.albedo"), Target::Albedo));
    EXPECT_EQ(viewSteps(PipelineKind::Deferred, {"depth", "final"}),
              (std::vector<std::string>{"TerrainHeightsPass", "ClearPass.gbuffer", "TerrainPass.gbuffer",
                                        "VegetationPass.gbuffer", "WaterMaskPass", "DebugViewPass.depth",
                                        "DebugViewPass.final"}));
    EXPECT_TRUE(viewSteps(PipelineKind::Deferred, {}).empty()) << "a whole frame's graph ends at its outputs";
}

// What a view's frame saves, in fragment invocations counted by the driver (frame/frame_traffic.h):
// printed, not asserted beyond "not more".
TEST_F(FrameSink, AViewsFrameCostsNoMoreFragmentsThanAWholeFrame) {
    std::string whyNot;
    if (!trafficCountable(&whyNot)) GTEST_SKIP() << whyNot;
    const SceneSettings scene = lakeScene(false);
    Renderer renderer(*shaders_, scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(320, 180, layoutNamed("compact"));
    for (PipelineKind kind : {PipelineKind::Deferred, PipelineKind::Forward}) {
        renderer.setPipeline(kind);
        auto invocations = [&](const std::vector<std::string>& sink) {
            renderer.views().setSink(sink);
            uint64_t total = 0;
            for (const PassTraffic& pass : measureFrameTraffic(renderer, scene).passes) total += pass.invocations;
            return total;
        };
        const uint64_t whole = invocations({});
        for (const char* view : {"final", "albedo", "radiance", "depth"}) {
            const uint64_t own = invocations({view});
            EXPECT_LE(own, whole) << view;
            std::printf("[ sink ] %s 320x180 compact, --view %s: %llu fragment invocations, whole frame %llu (%.0f%%)\n",
                        pipelineName(kind), view, (unsigned long long)own, (unsigned long long)whole,
                        whole ? 100.0 * double(own) / double(whole) : 0.0);
        }
    }
}

}  // namespace
}  // namespace oasis::gputest
