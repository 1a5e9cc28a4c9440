// A pass's declarations (what it reads and writes, the framebuffer of its writes) and the helpers
// shared by the passes that draw surfaces.
#include "passes/pass.h"

#include <algorithm>
#include <optional>

#include "render/light_paths.h"
#include "render/shadow_maps.h"
#include "render/texture_units.h"

namespace oasis {

const char* bufferName(Buffer buffer) {
    switch (buffer) {
        case Buffer::TerrainHeights: return "TerrainHeights";
        case Buffer::ShadowMaps: return "ShadowMaps";
        case Buffer::LightTiles: return "LightTiles";
        case Buffer::LightList: return "LightList";
        case Buffer::PlantInstances: return "PlantInstances";
    }
    return "?";
}

std::string resourceName(const Resource& resource) {
    if (auto target = std::get_if<Target>(&resource)) return targetName(*target);
    if (auto buffer = std::get_if<Buffer>(&resource)) return bufferName(*buffer);
    return "display";  // as the targets are named
}

bool isRead(Use use) { return use == Use::Sample || use == Use::DepthTest || use == Use::StencilTest; }
bool isWrite(Use use) { return !isRead(use); }

// The resources of `accesses` whose use `counts`, each once, in declared order.
static std::vector<Resource> resourcesUsed(const std::vector<Access>& accesses, bool (*counts)(Use)) {
    std::vector<Resource> used;
    for (const Access& access : accesses)
        if (counts(access.use) && std::find(used.begin(), used.end(), access.resource) == used.end())
            used.push_back(access.resource);
    return used;
}

std::vector<Resource> Pass::reads(const FrameSetup& frame) const { return resourcesUsed(accesses(frame), isRead); }
std::vector<Resource> Pass::writes(const FrameSetup& frame) const { return resourcesUsed(accesses(frame), isWrite); }

bool Pass::writes(const FrameSetup& frame, Target target) const {
    auto written = writes(frame);
    return std::find(written.begin(), written.end(), Resource(target)) != written.end();
}

void Pass::bindDeclaredOutputs(const PassContext& context) const {
    bindFramebufferOf(context.targets, accesses(context.frame));
}

namespace {
std::vector<Target>* boundTargetsRecord = nullptr;
}

void recordBoundTargets(std::vector<Target>* into) { boundTargetsRecord = into; }

void bindFramebufferOf(const FrameTargets& targets, const std::vector<Access>& accesses) {
    std::vector<Target> colour;
    std::optional<Target> depth;
    for (const Access& access : accesses) {
        const Target* target = std::get_if<Target>(&access.resource);
        if (!target || access.use == Use::Sample) continue;
        if (*target == Target::DepthStencil || *target == Target::SceneDepth) {
            depth = *target;
        } else if (std::find(colour.begin(), colour.end(), *target) == colour.end()) {
            colour.push_back(*target);
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, targets.framebuffer(colour, depth));
    if (boundTargetsRecord) {
        boundTargetsRecord->insert(boundTargetsRecord->end(), colour.begin(), colour.end());
        if (depth) boundTargetsRecord->push_back(*depth);
    }
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
               frame.reflectionTargets, frame.frameBlock, frame.reflectionFrameRange,
               frame.drawDepthStencilReads, frame.depthClamp, frame.flushBeforeComputeRead,
               frame.producedBuffers} {
    if (reduced_)
        glBindBufferRange(GL_UNIFORM_BUFFER, kFrameBlockBinding, frame.frameBlock, frame.reflectionFrameRange,
                          sizeof(FrameData));
}

ReflectionContext::~ReflectionContext() {
    if (reduced_) glBindBufferRange(GL_UNIFORM_BUFFER, kFrameBlockBinding, context_.frameBlock, 0, sizeof(FrameData));
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

std::vector<Access> SurfacePass::accesses(const FrameSetup& frame) const {
    std::vector<Access> used;
    for (Target target : surfaceOutputTargets(frame, output_, mirroring_)) used.push_back({target, Use::Write});
    if (mirroring_ == Mirroring::Direct)
        appendDepthStencil(used, {Use::DepthTest, Use::DepthWrite, Use::StencilWrite});
    else  // inside the water only (beginMirroredDraw)
        appendDepthStencil(used, {Use::DepthTest, Use::DepthWrite, Use::StencilTest});
    if (output_ == SurfaceOutput::Forward && frame.shadowsActive) used.push_back({Buffer::ShadowMaps, Use::Sample});
    // Shaded here: the fragments loop over the point lights.
    if (output_ == SurfaceOutput::Forward) used.push_back({Buffer::LightList, Use::Sample});
    return used;
}

bool SurfacePass::active(const FrameSetup& frame) const { return mirroredPassActive(frame, mirroring_); }

void SurfacePass::beginSurfaceDraw(PassContext& context, int stencilMark) const {
    bindDeclaredOutputs(context);
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

// Binds `target` of `targets` on its unit in kInputBindings.
static void bindSampledTarget(const FrameTargets& targets, Target target) {
    for (const InputBinding& row : kInputBindings) {
        if (row.resource != Resource(target)) continue;
        glActiveTexture(GLenum(GL_TEXTURE0 + row.binding));
        glBindTexture(GL_TEXTURE_2D, targets.texture(target));
        // The stencil view switches the target to stencil sampling; what samples it reads depth.
        if (target == Target::DepthStencil)
            glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
    }
    glActiveTexture(GL_TEXTURE0);
}

void bindDeclaredInputs(const std::vector<Access>& accesses, const PassContext& context) {
    for (const Access& access : accesses) {
        if (access.use != Use::Sample) continue;
        if (const Target* target = std::get_if<Target>(&access.resource)) {
            bindSampledTarget(context.targets, *target);
            continue;
        }
        for (const InputBinding& row : kInputBindings) {
            if (row.resource != access.resource) continue;
            if (row.slot == InputSlot::TextureArray && context.shadowMaps) context.shadowMaps->bind();
            if (row.slot != InputSlot::StorageBlock && row.slot != InputSlot::UniformBlock) continue;
            for (const auto& [buffer, name] : context.producedBuffers)
                if (Resource(buffer) == row.resource)
                    glBindBufferBase(row.slot == InputSlot::StorageBlock ? GL_SHADER_STORAGE_BUFFER : GL_UNIFORM_BUFFER,
                                     GLuint(row.binding), name);
        }
    }
}

void bindGBufferInputs(const FrameTargets& targets) {
    for (Target target : {Target::Albedo, Target::Normal, Target::Position, Target::Info})
        bindSampledTarget(targets, target);
    if (targets.layout().positionFromDepth()) bindSampledTarget(targets, Target::DepthStencil);
}

const char* surfaceOutputName(SurfaceOutput output) {
    return output == SurfaceOutput::GBuffer ? "gbuffer" : "forward";
}

std::vector<Target> surfaceOutputTargets(const FrameSetup& frame, SurfaceOutput output, Mirroring mirroring) {
    if (output == SurfaceOutput::GBuffer) {
        if (frame.positionFromDepth) return {Target::Albedo, Target::Normal, Target::Info};
        return {Target::Albedo, Target::Normal, Target::Position, Target::Info};
    }
    if (mirroring == Mirroring::Mirrored) return {Target::Reflection};
    if (toneMapFusedInto(frame, output, mirroring)) return {Target::Radiance, Target::Final};
    return {Target::Radiance};
}

std::vector<Access> gbufferSamples(const FrameSetup& frame, DepthRead depthRead) {
    std::vector<Access> samples;
    for (Target target : surfaceOutputTargets(frame, SurfaceOutput::GBuffer)) samples.push_back({target, Use::Sample});
    if (frame.positionFromDepth)
        samples.push_back({depthRead == DepthRead::FromCopy ? Target::SceneDepth : Target::DepthStencil, Use::Sample});
    return samples;
}

void appendDepthStencil(std::vector<Access>& accesses, std::initializer_list<Use> uses) {
    for (Use use : uses) accesses.push_back({Target::DepthStencil, use});
}

}  // namespace oasis
