// The renderer: owns the shader library, the scene's GPU data, the frame targets, both pipelines
// (built once; switching only changes which runs) and the debug views. The window app, the
// headless commands and the tests all drive this same object. Its choices from what the context
// offers (depth convention, lights path, water bounds, light method) are in renderer_choices.cpp;
// what its frames leave is read back with frame/frame_readback.h.
#pragma once
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
    // The paths chosen from the capabilities and the last frame's scene, with their reasons.
    const RenderPaths& paths() const { return paths_; }
    void setPipeline(PipelineKind kind) { active_ = kind; }
    PipelineKind pipeline() const { return active_; }
    // The last frame's graph: its pipeline's passes, which ran and why the others were culled.
    FrameGraph frameGraph() const;
    // The debug views of the last frame (frame/frame_views.h): what they are drawn with, which the
    // frames are culled for, drawing and reading one.
    FrameViews& views() { return views_; }
    const FrameViews& views() const { return views_; }
    // The plants placed around the last frame's camera and what that frame drew of them.
    const VegetationField& vegetation() const { return vegetationField_; }

    // Renders the scene with the active pipeline into Final (and the G-buffer when deferred).
    // A scene whose terrain grid density differs from the last frame's rebuilds the grid first.
    // With `stopBefore`, the frame ends before that pass so its inputs can be inspected; throws
    // std::invalid_argument (listing the pipeline's passes) if no pass has that name.
    void renderFrame(const SceneSettings& scene, const std::string& stopBefore = {});
    // Builds every program the active pipeline's frame and `view` (a debug view name, or "") use,
    // by running them with GL_RASTERIZER_DISCARD: a frame of its own for capture tools, so the
    // frames after it hold drawing and no shader compiles. Costs the frame's vertex work.
    void buildPrograms(const SceneSettings& scene, const std::string& view);
    // The frame, calling `afterEach` after every pass that ran (frame/gpu_timer.h's queries).
    void renderFrameObserved(const SceneSettings& scene, const std::function<void(const Pass&)>& afterEach);
    // Makes the G-buffer, depth and stencil hold the last frame's surfaces with the water scene the
    // views ask for (frame/view_fill.h): what the views, the probe and the encoding error read.
    // A frame stopped early keeps what it reached (a forward one gets the direct scene's steps
    // that ran). views().scene() says what the views show at water pixels and why.
    void ensureGBuffer();
    // The last whole frame's surfaces drawn unrounded: the view fill of `scene` run into `exact`
    // (targets of the frame's size, depth convention and a float layout) instead of the G-buffer.
    // `probe --shading` reads a forward frame's surfaces there (frame/shading_probe.h).
    void fillExactSurfaces(const FrameTargets& exact, WaterScene scene);
    // With the tone map fused the water composite writes Final only, so Radiance holds what lies
    // under the water there; this lays the water onto Radiance as the separate pass would have
    // (the radiance view, the probe, readTarget). Once per frame, and only when something asks.
    void ensureRadiance();
    // The timing floor (passes/floor_pass.h) at the current size and layout; overwrites the targets.
    void renderFloor();
    // Shows the Display target in the bound window's framebuffer of the given size.
    void present(int windowWidth, int windowHeight);

    const FrameTargets& targets() const { return *targets_; }
    // The reflection's own targets when a frame drew it at a reduced resolution; null before.
    const FrameTargets* reflectionTargets() const { return reflectionTargets_.get(); }
    // The GPU memory of the frame's targets now (FrameTargets::heldBytes: what the graph's plan
    // left allocated after the last frame), the reduced reflection's included.
    // The last frame's targets with their lifetimes, as its plan gave them (render --graph).
    const std::vector<TargetLifetime>& targetLifetimes() const { return lifetimes_; }
    double targetMemoryBytes() const {
        return targets_->heldBytes() + (reflectionTargets_ ? reflectionTargets_->heldBytes() : 0.0);
    }
    const FrameSetup& lastFrame() const { return frame_; }
    ShaderLibrary& shaders() { return shaders_; }
    const SceneGeometry& geometry() const { return geometry_; }
    const ShadowMaps& shadowMaps() const { return shadowMaps_; }
    // The active pipeline's passes, as its frames run them (the GL objects a pass owns in them).
    const Pipeline& activePipeline() const { return pipelineOf(active_); }
    // The plants' instances the last frame uploaded (PlantInstances, frame/frame_graph.h's inputs).
    const VegetationBuffers& vegetationBuffers() const { return vegetationBuffers_; }


private:
    // frame/frame_readback.cpp's way in (defined there alone): the water's bounds buffer, the
    // surfaces' float target and their refill with their own depth.
    friend struct ReadbackAccess;
    friend class FrameViews;  // its views draw from the frame's targets, context and fill
    // After a whole frame, a layout that rebuilds positions from depth gets the mirrored view fill
    // (the water's depth covers the mirrored scene there): the G-buffer's own surfaces.
    void fillSurfacesWithTheirDepth();
    PassContext context();
    PassContext contextOver(const FrameTargets& targets, const FrameSetup& frame);
    // What decides this frame besides the scene (render/frame_setup.h): the targets, the paths,
    // the capabilities, the plants' atlas and the request.
    FrameConditions frameConditions(const SceneSettings& scene, const std::string& stopBefore) const;
    void prepareVegetation(const SceneSettings& scene);
    // The reduced reflection's targets (kept while the frame's size, layout and depth stay) and
    // its frame block, for a frame whose reflection is drawn at 1/frame_.reflectionDivisor.
    void prepareReducedReflection();
    void uploadLights();
    // The frame's sink; with `beyondFrame`, also the targets that live past the frame (the sink's,
    // and those the views' fill and the composite after the frame write), which lend no memory.
    std::vector<Resource> sinkOfFrame(bool stopped, std::vector<Target>* beyondFrame = nullptr) const;
    void runFrame(const SceneSettings& scene, const std::string& stopBefore,
                  const std::function<void(const Pass&)>& afterEach);
    const Pipeline& pipelineOf(PipelineKind kind) const;
    void forgetGBuffer();
    void fillStoppedFrame();

    ShaderLibrary& shaders_;
    SceneGeometry geometry_;
    std::unique_ptr<FrameTargets> targets_;
    std::unique_ptr<FrameTargets> reflectionTargets_;  // the reflection at a reduced resolution, while asked for
    gl::Buffer reflectionUniforms_;                     // frame data for those targets' size
    Pipeline forward_{PipelineKind::Forward}, deferred_{PipelineKind::Deferred};
    PipelineKind active_ = PipelineKind::Deferred;
    const PlantAtlas* plantAtlas_ = nullptr;
    VegetationField vegetationField_;
    VisibleWaterBound visibleWater_;  // the dry land the reflection's plant chunks are culled against
    std::optional<TerrainGridPlacement> lastGrid_;  // the last frame's grid: is the camera standing still?
    VegetationDrawList vegetationList_;
    VegetationBuffers vegetationBuffers_;
    FrameViews views_{*this};  // where the debug views' pass was: GL objects made in the same order
    FloorPass floor_;
    WaterCompositePass waterComposite_;  // ensureRadiance's separate composite
    PresentPass present_;
    ShadowMaps shadowMaps_;  // the sun's cascades, bound to their unit in every pass context
    FloatReadback positionsReadback_;  // readSurfacePositions' float target (frame/frame_readback.h)
    gl::Buffer frameUniforms_;
    gl::Buffer lightList_, lightCount_;  // one list of PointLights serves every path
    std::optional<LightsPath> labelledLightsPath_;  // the path lightList_'s label names
    std::string ssboMissingReason_ = "no GL 4.3 / ARB_shader_storage_buffer_object";
    gl::Buffer waterBounds_;  // four ints (common/water_bounds.glsl)
    gl::Query waterSeen_;     // did the water mask pass a sample? (the reflection renders only then)
    void chooseWaterBounds();  // from the SSBOs and the context's limits; sets the context defines
    // The layout drawn for `requested` (itself, or standard without 16-bit unorm targets) and why.
    const GBufferLayout& chooseGBufferLayout(const GBufferLayout& requested, std::string& reason) const;
    std::optional<GBufferLayout> layoutRequested_;  // configure's last request (a copy: callers may pass a temporary)
    RenderPaths paths_;
    FrameSetup frame_;
    const DepthConvention* depthRequested_ = &standardDepthConvention();
    ViewFill viewFill_;
    std::optional<WaterScene> gbufferHolds_;  // the fill the G-buffer holds for the last frame, if any
    std::string stoppedBefore_;  // the pass the last frame stopped before, "" for a whole frame
    bool stoppedGBufferCurrent_ = false;  // a stopped frame's G-buffer already holds what it reached
    std::vector<std::string> stepsRan_;  // the scene steps (Pass::sceneStep) the last frame ran
    bool radianceAwaitsWater_ = false;  // a fused frame's composite has not been laid onto Radiance
    std::vector<Resource> frameSinks_ = frameOutputs();  // the last frame's sink
    std::vector<TargetLifetime> lifetimes_;               // and its targets' lifetimes
};

}  // namespace oasis
