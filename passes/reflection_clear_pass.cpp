// A stencil-masked full-screen draw at the far plane with depth test ALWAYS: only the water
// pixels are touched, never the whole buffer, and the frame's Reflection target is not cleared. At
// a reduced resolution the reflection's own targets first get their water mask: the water plane,
// drawn without a depth test.
#include "passes/reflection_clear_pass.h"

#include <algorithm>

#include "passes/water_mask_pass.h"

namespace oasis {
namespace {

// The reduced reflection's depth-stencil cleared and its water marked wherever the plane lies,
// seen or hidden: the frame's depth is not at this size to test against, and the bilinear
// upsample's taps beside a shore then land on mirrored scene too, not on the clear colour.
// Its Reflection is cleared as well, so taps just outside the water read zero, never stale memory.
void markReducedWater(PassContext& reflection, int divisor) {
    const FrameTargets& targets = reflection.targets;
    bindFramebufferOf(targets,
                      atScale({{Target::Reflection, Use::Write}, {Target::DepthStencil, Use::StencilWrite}}, divisor));
    const GLfloat nothing[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, nothing);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glClearBufferfi(GL_DEPTH_STENCIL, 0, targets.depth().farPlaneWindowDepth, kStencilNothing);
    markWaterStencil(reflection, "water.mask.plane");  // no depth test: every point of the plane
}

}  // namespace

// The mirrored draw that resets the water's depth to the far plane: the mirrored scene's "nothing
// drawn". The compact G-buffer tells the sky by that depth alone (gbufferSkyAt); the layouts that
// store position also get their "nothing drawn" colour values there (Info's SKY flag).
static std::vector<Access> waterReset(const FrameSetup& frame, SurfaceOutput output) {
    std::vector<Access> reset;
    if (output == SurfaceOutput::GBuffer && !frame.positionFromDepth)
        for (Target target : surfaceOutputTargets(frame, output)) reset.push_back({target, Use::Write});
    appendDepthStencil(reset, {Use::DepthWrite, Use::StencilTest});
    return reset;
}

// No clear of the frame's Reflection: it is read only at water pixels (the composite and the
// upsample are stencil-masked to the water), and there every pixel is written each frame by the
// mirrored passes (a surface, else the mirrored sky) or the upsample; the views and the probe
// show it only there (black outside the water or with reflections off), and a frame stopped early
// has it cleared by ClearPass.
std::vector<Access> ReflectionClearPass::declaredAccesses(const FrameSetup& frame) const {
    if (!frame.reflectionsActive) return {};
    std::vector<Access> used = waterReset(frame, output_);
    if (runsIn_ != RunsIn::Frame || frame.reflectionDivisor == 1) return used;
    // The reduced reflection's own targets (accesses scales them), made here by markReducedWater:
    // its Reflection and depth-stencil cleared whole, the water marked in its stencil, which the
    // reset then tests (its own write, no earlier pass's).
    used.erase(std::remove_if(used.begin(), used.end(), [](const Access& access) { return isRead(access.use); }),
               used.end());
    used.insert(used.begin(), {{Target::Reflection, Use::Write}, {Target::DepthStencil, Use::Replace}});
    return used;
}

bool ReflectionClearPass::active(const FrameSetup& frame) const { return frame.reflectionsActive; }

void ReflectionClearPass::execute(PassContext& context) {
    // Only where water is seen: with no water in view nothing is touched at all.
    OnlyWhereWaterIsSeen onlyWithWater(context, true);
    PassContext& mirrored = context;  // at the reflection's scale: Pass::run bound its frame data
    const int divisor = drawnAtDivisor(context.frame);
    if (divisor > 1) markReducedWater(mirrored, divisor);
    std::vector<Access> reset = atScale(waterReset(mirrored.frame, output_), divisor);
    bindFramebufferOf(mirrored.targets, reset);
    bool writeGBuffer = reset.front().resource != targetAt(Target::DepthStencil, divisor);
    glColorMask(writeGBuffer, writeGBuffer, writeGBuffer, writeGBuffer);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    beginMirroredDraw(Mirroring::Mirrored);
    beginWaterBoundedDraw(mirrored);
    glUseProgram(mirrored.shaders.program(mirrored.targets.layout().program("gbuffer.clear")));
    mirrored.geometry.drawFullscreenTriangle();
    endWaterBoundedDraw(mirrored);
    endMirroredDraw(Mirroring::Mirrored);
    glDisable(GL_DEPTH_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace oasis
