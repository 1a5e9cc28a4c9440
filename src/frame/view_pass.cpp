// A debug view as a pass of the request's graph (frame/view_pass.h).
#include "frame/view_pass.h"

#include <algorithm>

#include "frame/frame_views.h"
#include "frame/renderer.h"

namespace oasis {

std::string ViewPass::name() const { return "DebugViewPass." + viewName(); }

std::vector<Access> ViewPass::declaredAccesses(const FrameSetup&) const {
    std::vector<Access> used;
    const GBufferLayout& layout = views_.renderer_.targets().layout();
    for (const DebugView& view : debugViews()) {
        if (view_ && view_ != &view) continue;
        for (const Resource& read : viewReads(view, layout))
            if (std::none_of(used.begin(), used.end(), [&](const Access& access) { return access.resource == read; }))
                used.push_back({read, Use::Sample});
    }
    used.push_back({Screen::Display, Use::Write});
    return used;
}

bool ViewPass::readsRadiance() const {
    return !view_ || view_->source == ViewSource::Radiance;
}

bool ViewPass::readsSurfaces() const { return !view_ || readsSceneSurfaces(*view_); }

void ViewPass::execute(PassContext& context) { views_.draw(context, view_); }

}  // namespace oasis
