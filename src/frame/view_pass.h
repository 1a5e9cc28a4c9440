// ViewPass: one debug view (or the overview) drawn into Display, as a pass of the request's graph
// (frame/frame_views.h): it samples what the view reads and writes the displayed image, so the
// frame is culled for it and `render --graph` lists it as DebugViewPass.<view>.
#pragma once
#include <string>
#include <vector>

#include "debug/debug_views.h"
#include "passes/pass.h"

namespace oasis {

class FrameViews;

class ViewPass : public Pass {
public:
    // `view`: a row of the views' table, or null for the overview (every view's reads).
    ViewPass(FrameViews& views, const DebugView* view) : views_(views), view_(view) {}
    std::string name() const override;
    std::vector<Access> declaredAccesses(const FrameSetup& frame) const override;
    // The view's table name ("overview" for the grid).
    std::string viewName() const { return view_ ? view_->name : kOverviewName; }
    // Whether the view reads Radiance with the water laid on, or the frame's surfaces as the
    // views' fill leaves them: what the request's graph puts before its view passes.
    bool readsRadiance() const;
    bool readsSurfaces() const;

protected:
    void execute(PassContext& context) override;

private:
    FrameViews& views_;
    const DebugView* view_;
};

}  // namespace oasis
