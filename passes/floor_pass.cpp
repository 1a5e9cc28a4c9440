// Write pass with depth (as the geometry pass does), then a read pass like the lighting pass.
#include "passes/floor_pass.h"

namespace oasis {

void FloorPass::execute(PassContext& context) {
    const FrameTargets& targets = context.targets;
    std::vector<Access> gbuffer;
    for (Target target : surfaceOutputTargets(context.frame, SurfaceOutput::GBuffer)) gbuffer.push_back({target, Use::Write});
    appendDepthStencil(gbuffer, {Use::DepthWrite});
    bindFramebufferOf(targets, gbuffer);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glUseProgram(context.shaders.program(targets.layout().program("floor.write")));
    context.geometry.drawFullscreenTriangle();
    glDisable(GL_DEPTH_TEST);

    bindFramebufferOf(targets, {{Target::Final, Use::Write}});  // the G-buffer bound as declared
    glUseProgram(context.shaders.program(targets.layout().program("floor.read")));
    context.geometry.drawFullscreenTriangle();
}

}  // namespace oasis
