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
    if (auto scaled = std::get_if<ScaledTarget>(&resource))
        return std::string(targetName(scaled->target)) + " at 1/" + std::to_string(scaled->divisor);
    if (auto buffer = std::get_if<Buffer>(&resource)) return bufferName(*buffer);
    return "display";  // as the targets are named
}

bool targetOf(const Resource& resource, Target& target, int& divisor) {
    if (auto full = std::get_if<Target>(&resource)) {
        target = *full;
        divisor = 1;
        return true;
    }
    if (auto scaled = std::get_if<ScaledTarget>(&resource)) {
        target = scaled->target;
        divisor = scaled->divisor;
        return true;
    }
    return false;
}

Resource targetAt(Target target, int divisor) {
    if (divisor == 1) return target;
    return ScaledTarget{target, divisor};
}

std::vector<Access> atScale(std::vector<Access> accesses, int divisor) {
    for (Access& access : accesses) {
        Target target;
        int ignored;
        if (targetOf(access.resource, target, ignored)) access.resource = targetAt(target, divisor);
    }
    return accesses;
}

static void unbindScaledSamplers(const std::vector<Access>& accesses);

int Pass::drawnAtDivisor(const FrameSetup& frame) const {
    const bool reduced = frame.reflectionsActive && frame.reflectionDivisor > 1;
    return reduced && !frameScaleOnly_ && drawsInReflectionTargets() ? frame.reflectionDivisor : 1;
}

std::vector<Access> Pass::accesses(const FrameSetup& frame) const {
    const int divisor = drawnAtDivisor(frame);
    return divisor == 1 ? declaredAccesses(frame) : atScale(declaredAccesses(frame), divisor);
}

void Pass::run(PassContext& context) {
    gl::DebugGroup group(name().c_str());
    const std::vector<Access> declared = accesses(context.frame);
    bindDeclaredInputs(declared, context);
    // The frame's data for the targets' size: the reduced reflection's range of the frame block.
    const bool reduced = drawnAtDivisor(context.frame) > 1 && context.frameBlock != 0;
    if (reduced)
        glBindBufferRange(GL_UNIFORM_BUFFER, kFrameBlockBinding, context.frameBlock, context.reflectionFrameRange,
                          sizeof(FrameData));
    execute(context);
    if (reduced) glBindBufferRange(GL_UNIFORM_BUFFER, kFrameBlockBinding, context.frameBlock, 0, sizeof(FrameData));
    unbindScaledSamplers(declared);
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
std::vector<Resource>* boundTargetsRecord = nullptr;
}

void recordBoundTargets(std::vector<Resource>* into) { boundTargetsRecord = into; }

void bindFramebufferOf(const FrameTargets& targets, const std::vector<Access>& accesses) {
    std::vector<Target> colour;
    std::optional<Target> depth;
    int divisor = 1;  // the scale of what it draws into (a sampled target's may be another)
    for (const Access& access : accesses) {
        Target target;
        int scale;
        if (access.use == Use::Sample || !targetOf(access.resource, target, scale)) continue;
        divisor = scale;
        if (target == Target::DepthStencil || target == Target::SceneDepth) {
            depth = target;
        } else if (std::find(colour.begin(), colour.end(), target) == colour.end()) {
            colour.push_back(target);
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, targets.framebuffer(colour, depth, divisor));
    if (boundTargetsRecord) {
        for (Target target : colour) boundTargetsRecord->push_back(targetAt(target, divisor));
        if (depth) boundTargetsRecord->push_back(targetAt(*depth, divisor));
    }
    glViewport(0, 0, targets.width(divisor), targets.height(divisor));
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

std::vector<Access> SurfacePass::declaredAccesses(const FrameSetup& frame) const {
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

// Binds `target` of `targets` at 1/divisor on its unit in kInputBindings: the row of the target at
// that scale where the table has one (the reduced Reflection the upsample reads), else the target's
// own row (the mirrored passes' G-buffer at the reflection's scale, read as at the frame's). A row
// of a reduced target reads it bilinearly, clamped at its edges (upsampled): by the targets' sampler
// object, which stays with the unit, not with the texture (pooled memory another target takes next).
static void bindSampledTarget(const FrameTargets& targets, Target target, int divisor = 1) {
    const Resource scaled = targetAt(target, divisor);
    const bool ownRow = std::any_of(kInputBindings.begin(), kInputBindings.end(),
                                    [&](const InputBinding& row) { return row.resource == scaled; });
    for (const InputBinding& row : kInputBindings) {
        if (row.resource != (ownRow ? scaled : Resource(target))) continue;
        glActiveTexture(GLenum(GL_TEXTURE0 + row.binding));
        glBindTexture(GL_TEXTURE_2D, targets.texture(target, divisor));
        if (ownRow && divisor > 1) glBindSampler(GLuint(row.binding), targets.upsamplingSampler());
        // The stencil view switches the target to stencil sampling; what samples it reads depth.
        if (target == Target::DepthStencil)
            glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
    }
    glActiveTexture(GL_TEXTURE0);
}

// The units of the reduced targets `accesses` sampled, back to their textures' own sampling.
static void unbindScaledSamplers(const std::vector<Access>& accesses) {
    for (const Access& access : accesses) {
        if (access.use != Use::Sample || !std::holds_alternative<ScaledTarget>(access.resource)) continue;
        for (const InputBinding& row : kInputBindings)
            if (row.resource == access.resource) glBindSampler(GLuint(row.binding), 0);
    }
}

void bindDeclaredInputs(const std::vector<Access>& accesses, const PassContext& context) {
    for (const Access& access : accesses) {
        if (access.use != Use::Sample) continue;
        Target target;
        int divisor;
        if (targetOf(access.resource, target, divisor)) {
            bindSampledTarget(context.targets, target, divisor);
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
