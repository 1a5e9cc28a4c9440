// ReflectionClearPass: clears Reflection every frame (so it never shows a stale mirror image) and,
// with reflections active, resets depth inside the water to the far plane (and, for the G-buffer,
// the "nothing drawn" values) so the mirrored scene is depth-tested against itself only.
#pragma once
#include "passes/pass.h"

namespace oasis {

class ReflectionClearPass : public Pass {
public:
    explicit ReflectionClearPass(SurfaceOutput output) : output_(output) {}
    std::string name() const override { return std::string("ReflectionClearPass.") + surfaceOutputName(output_); }
    std::vector<Target> reads() const override { return {Target::DepthStencil}; }
    std::vector<Target> writes() const override {
        if (output_ == SurfaceOutput::Forward) return {Target::Reflection, Target::DepthStencil};
        return {Target::Reflection, Target::Albedo, Target::Normal, Target::Position, Target::Info,
                Target::DepthStencil};
    }
protected:
    void execute(PassContext& context) override;

private:
    SurfaceOutput output_;
};

}  // namespace oasis
