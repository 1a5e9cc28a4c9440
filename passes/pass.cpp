// Helpers shared by the passes that draw surfaces.
#include "passes/pass.h"

#include "render/light_paths.h"
#include "render/texture_units.h"

namespace oasis {

void bindSurfaceOutput(const FrameTargets& targets, SurfaceOutput output, Mirroring mirroring, bool toneMapFused) {
    GLuint framebuffer = output == SurfaceOutput::GBuffer ? targets.gbufferFramebuffer()
                         : mirroring == Mirroring::Mirrored ? targets.reflectionFramebuffer()
                         : toneMapFused                     ? targets.radianceFinalFramebuffer()
                                                            : targets.radianceFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, targets.width(), targets.height());
}

void beginWaterBoundedDraw(const PassContext& context) {
    if (!context.waterBounds) return;
    // Bound whenever the programs declare it (the context can record it), used only when bounded.
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWaterBoundsStorageBinding, context.waterBounds);
    if (!context.frame.waterBounded) return;
    for (GLenum plane : {GL_CLIP_DISTANCE1, GL_CLIP_DISTANCE2, GL_CLIP_DISTANCE3, GL_CLIP_DISTANCE4}) glEnable(plane);
}

void endWaterBoundedDraw(const PassContext& context) {
    if (!context.waterBounds) return;
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWaterBoundsStorageBinding, 0);
    if (!context.frame.waterBounded) return;
    for (GLenum plane : {GL_CLIP_DISTANCE1, GL_CLIP_DISTANCE2, GL_CLIP_DISTANCE3, GL_CLIP_DISTANCE4}) glDisable(plane);
}

namespace {
bool gWaterClipByClipDistance = true;
}

void setWaterClipByClipDistance(bool on) { gWaterClipByClipDistance = on; }

OnlyWhereWaterIsSeen::OnlyWhereWaterIsSeen(const PassContext& context, bool reflectionWork)
    : conditional_(reflectionWork && context.waterSeen != 0) {
    if (conditional_) glBeginConditionalRender(context.waterSeen, GL_QUERY_WAIT);
}

OnlyWhereWaterIsSeen::~OnlyWhereWaterIsSeen() {
    if (conditional_) glEndConditionalRender();
}

ReflectionContext::ReflectionContext(const PassContext& frame)
    : reduced_(frame.reflectionTargets != nullptr),
      context_{reduced_ ? *frame.reflectionTargets : frame.targets, frame.shaders, frame.geometry, frame.frame,
               frame.vegetation, frame.waterBounds, frame.shadowMaps, frame.waterSeen,
               frame.reflectionTargets, frame.reflectionFrameBlock, frame.frameBlock} {
    if (reduced_) glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBlockBinding, frame.reflectionFrameBlock);
}

ReflectionContext::~ReflectionContext() {
    if (reduced_) glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBlockBinding, context_.frameBlock);
}

void beginMirroredDraw(Mirroring mirroring) {
    if (mirroring != Mirroring::Mirrored) return;
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, kStencilWater, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilMask(0x00);
    glFrontFace(GL_CW);
    if (gWaterClipByClipDistance) glEnable(GL_CLIP_DISTANCE0);
}

void endMirroredDraw(Mirroring mirroring) {
    if (mirroring != Mirroring::Mirrored) return;
    glDisable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glFrontFace(GL_CCW);
    if (gWaterClipByClipDistance) glDisable(GL_CLIP_DISTANCE0);
}

bool toneMapFusedInto(const FrameSetup& frame, SurfaceOutput output, Mirroring mirroring) {
    return frame.toneMapFused && output == SurfaceOutput::Forward && mirroring == Mirroring::Direct;
}

bool mirroredPassActive(const FrameSetup& frame, Mirroring mirroring) {
    return mirroring == Mirroring::Direct || frame.reflectionsActive;
}

SurfacePass::SurfacePass(const std::string& baseName, SurfaceOutput output, Mirroring mirroring)
    : output_(output),
      mirroring_(mirroring),
      name_(variantName(baseName, output, mirroring)),
      step_(baseName + (mirroring == Mirroring::Mirrored ? ".mirrored" : "")) {}

std::vector<Target> SurfacePass::writes() const {
    std::vector<Target> written = surfaceOutputTargets(output_, mirroring_);
    // The direct forward passes write Final too where the tone map is fused (toneMapFusedInto).
    if (output_ == SurfaceOutput::Forward && mirroring_ == Mirroring::Direct) written.push_back(Target::Final);
    return written;
}

bool SurfacePass::active(const FrameSetup& frame) const { return mirroredPassActive(frame, mirroring_); }

void SurfacePass::beginSurfaceDraw(PassContext& context, int stencilMark) const {
    bindSurfaceOutput(context.targets, output_, mirroring_, toneMapFusedInto(context.frame, output_, mirroring_));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(context.targets.depth().nearerFunc);
    glDepthMask(GL_TRUE);
    if (mirroring_ == Mirroring::Direct) {
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, stencilMark, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        glStencilMask(0xFF);
    }
    beginMirroredDraw(mirroring_);
}

GLuint SurfacePass::surfaceProgram(PassContext& context, const std::string& shaderBase) const {
    std::string program = variantName(shaderBase, output_, mirroring_);
    if (toneMapFusedInto(context.frame, output_, mirroring_)) program += ".tonemapped";
    if (output_ == SurfaceOutput::Forward) program += lightsVariantSuffix(context.frame.lightsPath);
    else program = context.targets.layout().program(program);
    return context.shaders.program(program);
}

void SurfacePass::endSurfaceDraw() const {
    endMirroredDraw(mirroring_);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
}

std::string variantName(const std::string& base, SurfaceOutput output, Mirroring mirroring) {
    return base + "." + surfaceOutputName(output) + (mirroring == Mirroring::Mirrored ? ".mirrored" : "");
}

void bindGBufferInputs(const FrameTargets& targets, DepthRead depthRead) {
    const std::pair<int, Target> inputs[] = {{kUnitAlbedo, Target::Albedo}, {kUnitNormal, Target::Normal},
                                             {kUnitPosition, Target::Position}, {kUnitInfo, Target::Info}};
    for (auto [unit, target] : inputs) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, targets.texture(target));
    }
    if (!targets.layout().positionFromDepth()) return;
    glActiveTexture(GL_TEXTURE0 + kUnitDepth);
    if (depthRead == DepthRead::FromCopy) {
        // Nothing switches the copy to stencil sampling, so it keeps GL's default depth mode.
        glBindTexture(GL_TEXTURE_2D, targets.texture(Target::SceneDepth));
    } else {
        // The stencil view switches the target to stencil sampling; depth is read here.
        glBindTexture(GL_TEXTURE_2D, targets.texture(Target::DepthStencil));
        glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
    }
}

const char* surfaceOutputName(SurfaceOutput output) {
    return output == SurfaceOutput::GBuffer ? "gbuffer" : "forward";
}

std::vector<Target> surfaceOutputTargets(SurfaceOutput output, Mirroring mirroring) {
    if (output == SurfaceOutput::GBuffer)  // Position too, though a layout may not store it
        return {Target::Albedo, Target::Normal, Target::Position, Target::Info, Target::DepthStencil};
    return {mirroring == Mirroring::Mirrored ? Target::Reflection : Target::Radiance, Target::DepthStencil};
}

}  // namespace oasis
