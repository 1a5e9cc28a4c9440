// Helpers shared by the passes that draw surfaces.
#include "passes/pass.h"

#include "render/texture_units.h"

namespace oasis {

void bindSurfaceOutput(const FrameTargets& targets, SurfaceOutput output) {
    glBindFramebuffer(GL_FRAMEBUFFER, output == SurfaceOutput::GBuffer ? targets.gbufferFramebuffer()
                                                                       : targets.finalFramebuffer());
    glViewport(0, 0, targets.width(), targets.height());
}

void bindGBufferInputs(const FrameTargets& targets) {
    const std::pair<int, Target> inputs[] = {{kUnitAlbedo, Target::Albedo}, {kUnitNormal, Target::Normal},
                                             {kUnitPosition, Target::Position}, {kUnitInfo, Target::Info}};
    for (auto [unit, target] : inputs) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, targets.texture(target));
    }
}

const char* surfaceOutputName(SurfaceOutput output) {
    return output == SurfaceOutput::GBuffer ? "gbuffer" : "forward";
}

std::vector<Target> surfaceOutputTargets(SurfaceOutput output) {
    if (output == SurfaceOutput::GBuffer)
        return {Target::Albedo, Target::Normal, Target::Position, Target::Info, Target::DepthStencil};
    return {Target::Final, Target::DepthStencil};
}

}  // namespace oasis
