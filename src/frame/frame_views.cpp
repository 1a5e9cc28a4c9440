// The renderer's debug views (frame/frame_views.h): their settings, their sink, and drawing or
// reading one from the last frame.
#include "frame/frame_views.h"

#include <algorithm>
#include <stdexcept>

#include "debug/debug_views.h"
#include "frame/renderer.h"

namespace oasis {

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

void FrameViews::requireInSink(const std::string& viewName) const {
    if (sink_.empty() || std::find(sink_.begin(), sink_.end(), viewName) != sink_.end() ||
        std::find(sink_.begin(), sink_.end(), kOverviewName) != sink_.end())
        return;
    std::string names;
    for (const std::string& name : sink_) names += (names.empty() ? "" : ", ") + name;
    throw std::logic_error("the view " + viewName + " was not asked for: the frame was culled for " + names +
                           " (Renderer::views().setSink)");
}

void FrameViews::render(const std::string& viewName) {
    PassContext passContext = renderer_.context();
    const DebugView* view = findDebugView(viewName);
    if (!view && viewName != kOverviewName)
        throw std::invalid_argument("no debug view named '" + viewName + "' (views: " + debugViewNames() + ")");
    requireInSink(viewName);
    // Only the views of Radiance ask for the water laid on: the final view (the window's every
    // frame) keeps the fused frame's saving.
    if (viewName == kOverviewName || view->source == ViewSource::Radiance) renderer_.ensureRadiance();
    if (viewName == kOverviewName || (view && readsSceneSurfaces(*view))) renderer_.ensureGBuffer();
    if (viewName == kOverviewName)
        debugViews_.drawOverview(passContext, stencilPath_, scene_.scene ? waterSceneName(*scene_.scene) : "as left");
    else
        debugViews_.drawView(passContext, *view, stencilPath_);
}

std::vector<float> FrameViews::readValues(const std::string& viewName) {
    const DebugView* view = findDebugView(viewName);
    if (!view) throw std::invalid_argument("no debug view named '" + viewName + "' with values (views: " +
                                           debugViewNames() + ")");
    requireInSink(viewName);
    if (view->source == ViewSource::Radiance) renderer_.ensureRadiance();
    if (readsSceneSurfaces(*view)) renderer_.ensureGBuffer();
    PassContext passContext = renderer_.context();
    return debugViews_.readValues(passContext, *view, stencilPath_);
}

}  // namespace oasis
