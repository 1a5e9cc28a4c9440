// ReflectionClearPass: clears Reflection every frame (so it never shows a stale mirror image) and,
// with reflections active, resets depth inside the water to the far plane (and, for the G-buffer,
// the "nothing drawn" values) so the mirrored scene is depth-tested against itself only. The views'
// fill of the mirrored scene (render/view_fill.h) keeps Reflection: the frame's reflection view.
#pragma once
#include "passes/pass.h"

namespace oasis {

class ReflectionClearPass : public Pass {
public:
    enum class ReflectionTarget { Cleared, Kept };
    explicit ReflectionClearPass(SurfaceOutput output, ReflectionTarget reflection = ReflectionTarget::Cleared)
        : output_(output), reflection_(reflection) {}
    std::string name() const override { return std::string("ReflectionClearPass.") + surfaceOutputName(output_); }
    std::vector<Access> accesses(const FrameSetup& frame) const override;
protected:
    void execute(PassContext& context) override;

private:
    SurfaceOutput output_;
    ReflectionTarget reflection_;
};

}  // namespace oasis
