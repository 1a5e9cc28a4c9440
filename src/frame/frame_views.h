// The renderer's debug views (Renderer::views()): what they are drawn with (the HDR exposure, the
// stencil view's path, the water scene, the plant atlas), which views the frames are culled for
// (the sink), and drawing one into Display or reading its values, from the last frame.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "debug/debug_view_pass.h"
#include "frame/view_fill.h"
#include "frame/view_pass.h"
#include "render/frame_targets.h"
#include "render/plant_atlas.h"

namespace oasis {

class Renderer;

class FrameViews {
public:
    // What the frames after this are looked at through (their sink): the views named (table
    // names or "overview"), and nothing else of them; empty (the default): anything, the whole
    // frame (frameOutputs()). A view's frame is one graph whose sink is the displayed image
    // (Screen::Display): the pipeline's passes, then the passes the views need after it (the
    // composite onto Radiance, the views' fill, one ViewPass per view), culled together; it runs
    // only the passes whose writes reach what the views read. A frame stopped early keeps the
    // whole frame's sink. render and readValues of a view whose pass is not in the last frame's
    // graph throw std::logic_error; a name that is no view throws std::invalid_argument.
    // `reads`: what a reader besides the views (the check's shading oracle) reads afterwards as the
    // frame leaves it (Radiance with the water laid on, as readTarget reads it); views needed too.
    void setSink(const std::vector<std::string>& views, const std::vector<Resource>& reads = {});
    const std::vector<std::string>& sink() const;
    void setStencilPath(StencilViewPath path);
    StencilViewPath stencilPath() const;
    // The plant atlas the atlas view shows (and the plants are drawn with); the caller keeps it
    // alive (nullptr: the view is black).
    void setPlantAtlas(const PlantAtlas* atlas);
    const PlantAtlas* plantAtlas() const;
    // The HDR views' (radiance, reflection-raw) exposure, in stops.
    void setExposure(float stops);
    float exposure() const;
    // The water scene the views ask the G-buffer to hold (frame/view_fill.h, ensureGBuffer below);
    // scene() says what the views show at water pixels and why.
    void setWaterScene(WaterScene scene);
    WaterScene waterScene() const;
    const ViewScene& scene() const;
    // Makes the G-buffer, depth and stencil hold the last frame's surfaces with the water scene the
    // views ask for (frame/view_fill.h): what the views, the probe and the encoding error read.
    // A frame stopped early keeps what it reached (a forward one gets the direct scene's steps
    // that ran). scene() says what the views show at water pixels and why.
    void ensureGBuffer();
    // The last whole frame's surfaces drawn unrounded: the view fill of `scene` run into `exact`
    // (targets of the frame's size, depth convention and a float layout) instead of the G-buffer.
    // `probe --shading` reads a forward frame's surfaces there (frame/shading_probe.h).
    void fillExactSurfaces(const FrameTargets& exact, WaterScene scene);
    // With the tone map fused the water composite writes Final only, so Radiance holds what lies
    // under the water there; this lays the water onto Radiance as the separate pass would have
    // (the radiance view, the probe, readTarget). Once per frame, and only when something asks.
    void ensureRadiance();
    // Draws a debug view (by table name, or "overview") of the last frame into Display. A view of
    // a G-buffer target after a forward frame first fills the G-buffer with the geometry passes.
    void render(const std::string& viewName);
    // The numbers behind a view (not the overview) of the last frame: its viewValue() per pixel,
    // RGBA floats, bottom row first; the table's `values` name the channels.
    std::vector<float> readValues(const std::string& viewName);

private:
    // Its owner, which reads the views' state while it builds and fills the frame (the sink, the
    // water scene) and reaches the views' drawing; these reach the renderer's frame in turn.
    friend class Renderer;
    friend class ViewPass;  // draws through debugViews_ with the views' settings
    explicit FrameViews(Renderer& renderer);
    void requireInGraph(const std::string& viewName) const;
    // The pass of a view (table name or "overview"); the sink's, in the sink's order.
    ViewPass& passOf(const std::string& viewName) const;
    std::vector<const ViewPass*> sinkPasses() const;
    void draw(PassContext& context, const DebugView* view);  // ViewPass::execute: null, the overview

    Renderer& renderer_;
    std::vector<std::unique_ptr<ViewPass>> passes_;  // one per view of the table, then the overview
    DebugViewPass debugViews_;
    StencilViewPath stencilPath_ = StencilViewPath::Texturing;
    WaterScene waterScene_ = WaterScene::Direct;
    ViewScene scene_;  // what the G-buffer holds at water pixels for the views, and why
    std::vector<std::string> sink_;  // setSink's views; empty: the whole frame
    std::vector<Resource> sinkReads_;  // setSink's reads
};

}  // namespace oasis
