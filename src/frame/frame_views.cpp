// The renderer's debug views (frame/frame_views.h): their settings, their sink, and drawing or
// reading one from the last frame.
#include "frame/frame_views.h"

#include <algorithm>
#include <stdexcept>

#include "debug/debug_views.h"
#include "frame/renderer.h"

namespace oasis {

FrameViews::FrameViews(Renderer& renderer) : renderer_(renderer) {
    for (const DebugView& view : debugViews()) passes_.push_back(std::make_unique<ViewPass>(*this, &view));
    passes_.push_back(std::make_unique<ViewPass>(*this, nullptr));
}

ViewPass& FrameViews::passOf(const std::string& viewName) const {
    for (const auto& pass : passes_)
        if (pass->viewName() == viewName) return *pass;
    throw std::invalid_argument("no debug view named '" + viewName + "' (views: " + debugViewNames() + ")");
}

std::vector<const ViewPass*> FrameViews::sinkPasses() const {
    std::vector<const ViewPass*> shown;
    for (const std::string& name : sink_) shown.push_back(&passOf(name));
    return shown;
}

void FrameViews::ensureGBuffer() { renderer_.ensureGBuffer(); }
void FrameViews::fillExactSurfaces(const FrameTargets& exact, WaterScene scene) {
    renderer_.fillExactSurfaces(exact, scene);
}
void FrameViews::ensureRadiance() { renderer_.ensureRadiance(); }

void FrameViews::setSink(const std::vector<std::string>& views, const std::vector<Resource>& reads) {
    for (const std::string& name : views)
        if (name != kOverviewName && !findDebugView(name))
            throw std::invalid_argument("no debug view named '" + name + "' (views: " + debugViewNames() + ")");
    if (views.empty() && !reads.empty())
        throw std::invalid_argument("FrameViews::setSink: reads besides the views need the views named "
                                    "(no views: the whole frame, which holds them anyway)");
    sink_ = views;
    sinkReads_ = reads;
}

const std::vector<std::string>& FrameViews::sink() const { return sink_; }
void FrameViews::setStencilPath(StencilViewPath path) { stencilPath_ = path; }
StencilViewPath FrameViews::stencilPath() const { return stencilPath_; }
const PlantAtlas* FrameViews::plantAtlas() const { return renderer_.plants_.atlas; }
void FrameViews::setExposure(float stops) { debugViews_.setExposureStops(stops); }
float FrameViews::exposure() const { return debugViews_.exposureStops(); }
void FrameViews::setWaterScene(WaterScene scene) { waterScene_ = scene; }
WaterScene FrameViews::waterScene() const { return waterScene_; }
const ViewScene& FrameViews::scene() const { return scene_; }

void FrameViews::setPlantAtlas(const PlantAtlas* atlas) {
    renderer_.plants_.atlas = atlas;
    debugViews_.setPlantAtlasTexture(atlas ? atlas->texture() : 0);
    if (atlas)
        renderer_.plants_.buffers.setAtlas(atlas->texture(), atlas->columns(), atlas->rows());
    else
        renderer_.plants_.buffers.setAtlas(0, 1, 1);
}

void FrameViews::requireInGraph(const std::string& viewName) const {
    if (sink_.empty()) return;
    // The graph of a frame built for views ends in their passes: the view's, or the overview's
    // (every view's reads). A frame stopped early keeps the whole frame's sink: the views named
    // may be drawn.
    const FrameGraph& graph = renderer_.left_.graph;
    const bool stopped = !renderer_.left_.stoppedBefore.empty();
    auto named = [&](const std::string& name) { return std::find(sink_.begin(), sink_.end(), name) != sink_.end(); };
    if (stopped ? named(viewName) || named(kOverviewName)
                : graph.runs(passOf(viewName).name()) || graph.runs(passOf(kOverviewName).name()))
        return;
    std::string names;
    for (const std::string& name : sink_) names += (names.empty() ? "" : ", ") + name;
    throw std::logic_error("the view " + viewName + " is not in the last frame's graph: it was culled for " + names +
                           " (Renderer::views().setSink)");
}

void FrameViews::render(const std::string& viewName) {
    ViewPass& pass = passOf(viewName);
    requireInGraph(viewName);
    // Only the views of Radiance ask for the water laid on: the final view (the window's every
    // frame) keeps the fused frame's saving.
    if (pass.readsRadiance()) renderer_.ensureRadiance();
    if (pass.readsSurfaces()) renderer_.ensureGBuffer();
    PassContext passContext = renderer_.context();
    runValidated(pass, passContext);
}

void FrameViews::draw(PassContext& context, const DebugView* view) {
    if (!view)
        debugViews_.drawOverview(context, stencilPath_, scene_.scene ? waterSceneName(*scene_.scene) : "as left");
    else
        debugViews_.drawView(context, *view, stencilPath_);
}

std::vector<float> FrameViews::readValues(const std::string& viewName) {
    const DebugView* view = findDebugView(viewName);
    if (!view) throw std::invalid_argument("no debug view named '" + viewName + "' with values (views: " +
                                           debugViewNames() + ")");
    requireInGraph(viewName);
    if (view->source == ViewSource::Radiance) renderer_.ensureRadiance();
    if (readsSceneSurfaces(*view)) renderer_.ensureGBuffer();
    PassContext passContext = renderer_.context();
    return debugViews_.readValues(passContext, *view, stencilPath_);
}

}  // namespace oasis
