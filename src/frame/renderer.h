// The renderer: owns the shader library, the scene's GPU data, the frame targets, both pipelines
// (built once; switching only changes which runs) and the debug views. The window app, the
// headless commands and the tests all drive this same object. Its choices from what the context
// offers (depth convention, lights path, water bounds, light method) are in renderer_choices.cpp;
// what its frames leave is read back with frame/frame_readback.h.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "debug/debug_view_pass.h"
#include "frame/frame_views.h"
#include "frame/pipeline.h"
#include "frame/render_paths.h"
#include "frame/view_fill.h"
#include "passes/floor_pass.h"
#include "passes/present_pass.h"
#include "passes/water_composite_pass.h"
#include "render/float_readback.h"
#include "render/frame_setup.h"
#include "render/frame_targets.h"
#include "render/image.h"
#include "render/plant_atlas.h"
#include "render/scene_geometry.h"
#include "render/shader_library.h"
#include "render/shadow_maps.h"
#include "render/vegetation_buffers.h"
#include "scene/vegetation.h"

namespace oasis {

// What a frame is asked for besides its scene (Renderer::renderFrame): where it stops, who is
// told after each pass, or only its programs built. A pass name converts to a request to stop there.
struct FrameRequest {
    FrameRequest() = default;
    FrameRequest(std::string stopBefore) : stopBefore(std::move(stopBefore)) {}
    FrameRequest(const char* stopBefore) : stopBefore(stopBefore) {}
    // The frame, calling `afterEach` after every pass that ran (frame/gpu_timer.h's queries).
    static FrameRequest observed(std::function<void(const Pass&)> afterEach);
    // Builds every program the frame and `view` (a debug view name, or "") use, by running them
    // with GL_RASTERIZER_DISCARD: a frame of its own for capture tools, so the frames after it hold
    // drawing and no shader compiles. Costs the frame's vertex work.
    static FrameRequest buildingPrograms(std::string view);

    // With a pass name, the frame ends before that pass so its inputs can be inspected; a name no
    // pass has throws std::invalid_argument (listing the pipeline's passes).
    std::string stopBefore;
    std::function<void(const Pass&)> afterEach;
    bool programsOnly = false;
    std::string programsView;  // with programsOnly: the view whose programs are built too
};

// What the last frame was and left (Renderer::lastFrame()), for the tools that read it after.
struct LastFrame {
    const FrameSetup& setup;  // its description
    // Its targets with their lifetimes, as its plan gave them (render --graph).
    const std::vector<TargetLifetime>& targetLifetimes;
    const VegetationField& vegetation;        // the plants placed around its camera, what it drew of them
    const VegetationBuffers& plantInstances;  // the instances it uploaded (PlantInstances, frame_graph.h)
    const Pipeline& pipeline;                 // its pipeline's passes (the GL objects a pass owns in them)
    const FrameGraph& requestGraph;           // its graph (Renderer::renderFrame)
    const FrameTargets& targets;  // the reduced reflection's among them, at their scale
    // Its graph: the pipeline's passes, then (a frame for named views) the views' passes after
    // it, ending in the displayed image; which ran and why the others were culled.
    const FrameGraph& graph() const { return requestGraph; }
    // The GPU memory of its targets (FrameTargets::heldBytes: what the graph's plan left
    // allocated after it), the reduced reflection's included.
    double targetMemoryBytes() const { return targets.heldBytes(); }
};

// What frames are drawn with, lent to the tools that draw or read beside them (the probes, the
// read-backs, the check's oracle and buffer search).
struct RendererParts {
    ShaderLibrary& shaders;
    const SceneGeometry& geometry;
    const ShadowMaps& shadowMaps;  // the sun's cascades
};

class Renderer {
public:
    Renderer(ShaderLibrary& shaders, const SceneSettings& scene);

    // Reallocates the targets when the size or layout changes; scene data is kept. Throws
    // std::runtime_error (naming the size) when the targets cannot be made, keeping the old ones.
    // A layout with a 16-bit unorm target the context cannot draw into (capabilities'
    // norm16Targets) falls back to standard; paths() says which is in use and why. Asking for the
    // layout a fallback put in use (a resize with targets().layout()) keeps the request and reason.
    void configure(int width, int height, const GBufferLayout& layout);
    // What the context offers (frame/render_paths.h), given once and whole: replaces the
    // constructor's own measure (a session's report honours --force). Rechooses the paths in
    // order: the lights' path and the water's bounds, the light method, the depth convention
    // (reallocating the targets when the one in use changes), the read-only depth, the G-buffer
    // layout (reallocating when the one in use changes).
    void setCapabilities(const RendererCapabilities& capabilities);
    // The depth convention (render/depth_convention.h) asked for; reversed-z needs glClipControl
    // and falls back to standard without it. Reallocates the targets when the convention in use
    // changes; paths() says which is in use and why.
    void setDepthConvention(const DepthConvention& requested);
    void setPipeline(PipelineKind kind) { active_ = kind; }
    PipelineKind pipeline() const { return active_; }
    // The paths chosen from the capabilities and the last frame's scene, with their reasons.
    const RenderPaths& paths() const { return paths_; }

    // Renders the scene with the active pipeline into Final (and the G-buffer when deferred), as
    // `request` asks (FrameRequest: whole, stopped before a pass, observed, or programs only).
    // A scene whose terrain grid density differs from the last frame's rebuilds the grid first.
    void renderFrame(const SceneSettings& scene, const FrameRequest& request = {});
    // The timing floor (passes/floor_pass.h) at the current size and layout; overwrites the targets.
    void renderFloor();
    // Shows the Display target in the bound window's framebuffer of the given size.
    void present(int windowWidth, int windowHeight);

    // The debug views of the last frame (frame/frame_views.h): what they are drawn with, which the
    // frames are culled for, the fills that make the targets hold what they show, drawing and
    // reading one.
    FrameViews& views() { return views_; }
    const FrameViews& views() const { return views_; }
    const FrameTargets& targets() const { return *targets_; }
    LastFrame lastFrame() const {
        return {frame_, left_.lifetimes, plants_.field, plants_.buffers, pipelineOf(active_), left_.graph,
                *targets_};
    }
    RendererParts parts() const { return {shaders_, geometry_, shadowMaps_}; }

private:
    // frame/frame_readback.cpp's way in (defined there alone): the water's bounds buffer, the
    // surfaces' float target and their refill with their own depth.
    friend struct ReadbackAccess;
    friend class FrameViews;  // its views draw from the frame's targets, context and fill
    // FrameViews' fills (frame/frame_views.h says what each does), kept here beside the frame
    // state they read and reset.
    void ensureGBuffer();
    void fillExactSurfaces(const FrameTargets& exact, WaterScene scene);
    void ensureRadiance();
    // After a whole frame, a layout that rebuilds positions from depth gets the mirrored view fill
    // (the water's depth covers the mirrored scene there): the G-buffer's own surfaces.
    void fillSurfacesWithTheirDepth();
    PassContext context();
    PassContext contextOver(const FrameTargets& targets, const FrameSetup& frame);
    // What decides this frame besides the scene (render/frame_setup.h): the targets, the paths,
    // the capabilities, the plants' atlas and the request.
    FrameConditions frameConditions(const SceneSettings& scene, const std::string& stopBefore) const;
    void prepareVegetation(const SceneSettings& scene);
    // The reduced reflection's range of the frame block, for a frame whose reflection is drawn at
    // 1/frame_.reflectionDivisor: the frame's data for its targets' size.
    void prepareReducedReflection();
    void uploadLights();
    // The frame's graph (frame_graph.h), one for the request: the pipeline's passes, then for named
    // views (FrameViews::setSink) the passes they need after the frame (the composite onto
    // Radiance for a view of it, the views' fill for a view of the surfaces, one ViewPass each),
    // culled from the displayed image; a whole frame's ends at frameOutputs(), and a frame stopped
    // before the pass `stopBefore` (not empty) is the whole frame's cut there (cutAt).
    // `beyondFrame` gets the targets that live past the frame (what the views' passes touch, as
    // they run when each view is drawn; all of them for a whole frame), which lend no memory.
    FrameGraph requestGraph(const std::string& stopBefore, std::vector<Target>& beyondFrame) const;
    void runFrame(const SceneSettings& scene, const std::string& stopBefore,
                  const std::function<void(const Pass&)>& afterEach);
    const Pipeline& pipelineOf(PipelineKind kind) const;
    void forgetGBuffer();
    void fillStoppedFrame();

    // The plants: the atlas they are drawn with, those placed around the camera, the dry land the
    // reflection's plant chunks are culled against, the last frame's grid (is the camera standing
    // still?), the frame's draw list and its instance buffers.
    struct Plants {
        const PlantAtlas* atlas = nullptr;
        VegetationField field;
        VisibleWaterBound visibleWater;
        std::optional<TerrainGridPlacement> lastGrid;
        VegetationDrawList list;
        VegetationBuffers buffers;
    };
    // The passes run outside the pipelines: the timing floor, the composite onto Radiance (a step
    // of a Radiance view's graph, run by ensureRadiance), and present.
    struct LonePasses {
        FloorPass floor;
        WaterCompositePass waterComposite{true};
        PresentPass present;
    };
    // One list of PointLights serves every path (SSBO or UBO), with its count; the path the list's
    // label names, and why there is no SSBO path where there is none.
    struct LightBuffers {
        gl::Buffer list, count;
        std::optional<LightsPath> labelledPath;
        std::string ssboMissingReason = "no GL 4.3 / ARB_shader_storage_buffer_object";
    };
    // The water's records on the GPU: its visible rectangle (four ints, common/water_bounds.glsl)
    // and whether the water mask passed a sample (the reflection renders only then).
    struct WaterRecords {
        gl::Buffer bounds;
        gl::Query seen;
    };
    // What the last frame left for the fills and views after it.
    struct FrameLeft {
        std::optional<WaterScene> gbufferHolds;  // the fill the G-buffer holds for it, if any
        std::string stoppedBefore;               // the pass it stopped before, "" for a whole frame
        bool stoppedGBufferCurrent = false;      // a stopped frame's G-buffer already holds what it reached
        std::vector<std::string> stepsRan;       // the scene steps (Pass::sceneStep) it ran
        bool radianceAwaitsWater = false;        // a fused frame's composite has not been laid onto Radiance
        FrameGraph graph;                              // its graph (requestGraph)
        std::vector<TargetLifetime> lifetimes;         // and its targets' lifetimes
    };
    // What was asked for, kept so a fallback is decided again when the capabilities change:
    // configure's last layout (a copy: callers may pass a temporary) and the depth convention.
    struct Requests {
        std::optional<GBufferLayout> layout;
        const DepthConvention* depth = &standardDepthConvention();
    };
    void chooseWaterBounds();  // from the SSBOs and the context's limits; sets the context defines
    // The layout drawn for `requested` (itself, or standard without 16-bit unorm targets) and why.
    const GBufferLayout& chooseGBufferLayout(const GBufferLayout& requested, std::string& reason) const;

    ShaderLibrary& shaders_;
    SceneGeometry geometry_;
    std::unique_ptr<FrameTargets> targets_;
    Pipeline forward_{PipelineKind::Forward}, deferred_{PipelineKind::Deferred};
    PipelineKind active_ = PipelineKind::Deferred;
    Plants plants_;
    FrameViews views_{*this};  // where the debug views' pass was: GL objects made in the same order
    LonePasses lonePasses_;
    ShadowMaps shadowMaps_;  // the sun's cascades, bound to their unit in every pass context
    FloatReadback positionsReadback_;  // readSurfacePositions' float target (frame/frame_readback.h)
    gl::Buffer frameUniforms_;
    LightBuffers lights_;
    WaterRecords water_;
    Requests requested_;
    RenderPaths paths_;
    FrameSetup frame_;
    ViewFill viewFill_;
    FrameLeft left_;
};

}  // namespace oasis
