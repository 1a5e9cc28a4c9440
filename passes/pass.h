// A render pass: it names itself, declares the targets it reads and writes, and executes a short
// list of GL calls inside a KHR_debug group of its name. A pipeline is an ordered list of passes.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "gl/objects.h"
#include "render/frame_resource.h"
#include "render/frame_setup.h"
#include "render/frame_targets.h"
#include "render/scene_geometry.h"
#include "render/shader_library.h"
#include "render/surface_output.h"
#include "render/vegetation_buffers.h"

namespace oasis {

class ShadowMaps;

// What every pass may use while it executes.
struct PassContext {
    const FrameTargets& targets;
    ShaderLibrary& shaders;
    const SceneGeometry& geometry;
    const FrameSetup& frame;
    const VegetationBuffers& vegetation;
    // The rectangle of visible water (common/water_bounds.glsl): 0 where the context cannot record
    // it; recorded by WaterMaskPass, the reflection's passes clip to it when frame.waterBounded.
    GLuint waterBounds = 0;
    // The sun's cascaded shadow maps (render/shadow_maps.h): ShadowPass draws them, lighting reads them.
    ShadowMaps* shadowMaps = nullptr;
    // An occlusion query (GL_ANY_SAMPLES_PASSED) around WaterMaskPass's draw when the frame bounds
    // its reflection (frame.waterBounded), else 0: the reflection's passes render conditionally on it.
    GLuint waterSeen = 0;
    // The frame block (one buffer) and where in it the reduced reflection's range lies: the frame's
    // data for the reflection's targets at 1/frame.reflectionDivisor (screen, targetScale), bound
    // while a pass drawn at that scale runs (Pass::run), the frame's range (at 0) bound back after.
    // 0 and 0 at full resolution, and outside the frame (views, fills and probes).
    GLuint frameBlock = 0;
    GLintptr reflectionFrameRange = 0;
    // Whether depth and stencil must be drawn into colour targets to be read back (no glReadPixels
    // of them: OpenGL ES without GL_NV_read_depth_stencil, render/depth_stencil_readback.h).
    bool drawDepthStencilReads = false;
    // Whether GL_DEPTH_CLAMP may be enabled: not on OpenGL ES without GL_EXT_depth_clamp, nor in a
    // tier forced without it (--force gles30, no-depth-clamp). The water plane and the light
    // volumes draw clamped where they can; the shadow casters' fallback is render/shadow_cascades.h's.
    bool depthClamp = true;
    // The driver workaround flush-before-compute-read (gl/driver_workarounds.h): a dispatch that
    // reads a texture drawn this frame is preceded by a texture-fetch barrier.
    bool flushBeforeComputeRead = false;
    // The buffers passes of this frame made that they own (Pass::ownBuffer: the tile lists), the
    // last maker's: where a later pass that samples one finds it. Pipeline::run fills it in.
    std::vector<std::pair<Buffer, GLuint>> producedBuffers{};
};

// How a pass touches a resource. Write draws into part of it (blending or depth-tested draws keep
// the rest); Replace makes all of it anew (a copy, a compute pass), so what an earlier pass wrote
// there is dead. The depth and stencil uses attach the depth-stencil target.
enum class Use { Sample, Write, Replace, DepthTest, DepthWrite, StencilTest, StencilWrite };
struct Access {
    Resource resource;
    Use use;
};
bool isRead(Use use);   // Sample, DepthTest, StencilTest
bool isWrite(Use use);  // Write, Replace, DepthWrite, StencilWrite
// Binds each resource `accesses` samples where render/texture_units.h's kInputBindings reads it:
// the context's targets on their texture units (the depth-stencil target in depth mode), the
// shadow maps, and the buffers passes made (PassContext::producedBuffers). The point lights are
// the renderer's upload, bound before the first pass (Renderer::uploadLights); the terrain's
// heights and the plants' instances are vertex attributes, bound by the geometry that draws them.
void bindDeclaredInputs(const std::vector<Access>& accesses, const PassContext& context);

class Pass {
public:
    virtual ~Pass() = default;
    virtual std::string name() const = 0;
    // What the pass reads and writes in the frame it is given: the only truth about what it
    // touches. Framebuffers, culling and the frame's validation are derived from it. Its own
    // declaration (declaredAccesses) at the scale it draws at (drawnAtDivisor): the one place
    // where the reflection's passes' targets become the reduced reflection's.
    std::vector<Access> accesses(const FrameSetup& frame) const;
    // 1/divisor of the frame's size is where the pass draws: frame.reflectionDivisor for the frame's
    // reflection passes where the reflection is drawn reduced (drawsInReflectionTargets), else 1.
    int drawnAtDivisor(const FrameSetup& frame) const;
    // For the passes of the views' fills: they draw the mirrored scene into the frame's own
    // targets, whatever the frame's reflection resolution (frame/frame_assembly.h).
    void drawAtFrameScale() { frameScaleOnly_ = true; }
    std::vector<Resource> reads(const FrameSetup& frame) const;
    std::vector<Resource> writes(const FrameSetup& frame) const;
    bool writes(const FrameSetup& frame, Target target) const;
    // Whether the pass has work this frame by the frame's own settings (the mirrored passes only
    // with reflections on). Whether anyone needs its work is the frame graph's (frame/frame_graph.h).
    virtual bool active(const FrameSetup&) const { return true; }
    // The step of drawing the scene this pass does, named the same in both pipelines ("clear",
    // "TerrainPass", "TerrainPass.mirrored"): the link between a forward pass and its G-buffer
    // counterpart, by which a forward frame's G-buffer is filled for the views. "" for passes that
    // only shade, copy or compose.
    virtual std::string sceneStep() const { return {}; }
    // Whether the pass only draws the water's reflection: where the frame bounds its reflection,
    // it renders conditionally on the water mask's occlusion query, so a frame with no water in
    // view pays nothing for it (Pipeline::run).
    virtual bool reflectionWork() const { return false; }
    // Whether what it draws lands in the reflection's targets (maybe reduced): the mirrored passes,
    // and the reflection's clear, which binds them itself.
    virtual bool drawsInReflectionTargets() const { return reflectionWork(); }
    // Whether the pass clears every pixel of the targets it writes (glClear, no stencil, scissor or
    // clip): the pixel history then knows it wrote a pixel without asking an occlusion query, which
    // a clear never passes. A stencil-masked full-screen draw is not such a clear.
    virtual bool clearsWholeTargets(const FrameSetup&) const { return false; }
    // The GL buffer that holds `buffer` as this pass last wrote it, where the pass owns it (the
    // tile lists), else 0: what the check's pass-by-pass search reads (check/check_buffers.h).
    virtual GLuint ownBuffer(Buffer) const { return 0; }

    // Binds what the pass declares it samples (bindDeclaredInputs) and, drawn at a reduced scale,
    // the frame block's range of that scale; then executes it.
    void run(PassContext& context);

protected:
    // What the pass reads and writes, its targets named at the frame's size (accesses scales them).
    virtual std::vector<Access> declaredAccesses(const FrameSetup& frame) const = 0;
    virtual void execute(PassContext& context) = 0;
    // Binds the framebuffer of the pass's declared writes (and the depth-stencil target where it
    // tests or writes depth or stencil) and sets the viewport to the whole target.
    void bindDeclaredOutputs(const PassContext& context) const;

private:
    bool frameScaleOnly_ = false;
};

// The stencil value each kind of surface writes, shown by the stencil debug view.
enum StencilMark : int { kStencilNothing = 0, kStencilTerrain = 1, kStencilWater = 2, kStencilVegetation = 3 };

// A pass that draws scene surfaces (terrain, plants): into the G-buffer or shaded, as seen directly
// or mirrored in the water. It is named "<Base>.<output>[.mirrored]", after its shader variants.
class SurfacePass : public Pass {
public:
    SurfacePass(const std::string& baseName, SurfaceOutput output, Mirroring mirroring);
    std::string name() const override { return name_; }
    std::vector<Access> declaredAccesses(const FrameSetup& frame) const override;
    bool active(const FrameSetup& frame) const override;
    std::string sceneStep() const override { return step_; }
    bool reflectionWork() const override { return mirroring_ == Mirroring::Mirrored; }

protected:
    // Binds the output, depth-tests and writes depth; direct draws mark `stencilMark`, mirrored
    // draws stay inside the water (beginMirroredDraw). endSurfaceDraw restores the defaults.
    void beginSurfaceDraw(PassContext& context, int stencilMark) const;
    void endSurfaceDraw() const;
    // The program of a surface shader ("terrain", "vegetation") for this pass: shaded here
    // (forward), its fragments loop over the point lights through the frame's light path.
    GLuint surfaceProgram(PassContext& context, const std::string& shaderBase) const;

    SurfaceOutput output_;
    Mirroring mirroring_;

private:
    std::string name_;
    std::string step_;  // the base name, ".mirrored" for the mirrored draw
};

// Binds the framebuffer of `accesses` (its writes in order, the depth-stencil target where it is
// tested or written; targets of one scale) and sets the viewport to the whole target at that scale.
void bindFramebufferOf(const FrameTargets& targets, const std::vector<Access>& accesses);
// The accesses with every target at 1/divisor of the frame (buffers as they are).
std::vector<Access> atScale(std::vector<Access> accesses, int divisor);
// While `into` is set, bindFramebufferOf adds each target it attaches there: the frame's
// validation (frame/frame_graph.h) holds what a pass bound against what it declared.
void recordBoundTargets(std::vector<Resource>* into);
// Whether a pass shading into `output` writes Final too this frame (the fused tone map).
bool toneMapFusedInto(const FrameSetup& frame, SurfaceOutput output, Mirroring mirroring);
// Mirrored draws pass the stencil test only on water pixels, and flip the front face (a mirror
// reverses winding) and clip what lies below the water.
void beginMirroredDraw(Mirroring mirroring);
void endMirroredDraw(Mirroring mirroring);
// Whether the shaders clip the mirrored geometry with gl_ClipDistance[0] (GL_CLIP_DISTANCE0 is
// enabled around mirrored draws) or by discard (OpenGL ES without GL_EXT_clip_cull_distance, where
// the enum does not exist): the shader library's dialect decides, the renderer says it here.
void setWaterClipByClipDistance(bool on);
// The reflection's full-screen draws clip their triangle to the visible water (gl_ClipDistance
// 1-4, written by common/water_bounds.glsl in fullscreen.vert) when the frame records it.
void beginWaterBoundedDraw(const PassContext& context);
void endWaterBoundedDraw(const PassContext& context);
// Renders the scope's draws and clears only if the water mask's occlusion query saw a water
// sample (GL_QUERY_WAIT: the query's result, not a guess), where `reflectionWork` and the frame has
// the query; else the scope changes nothing.
class OnlyWhereWaterIsSeen {
public:
    OnlyWhereWaterIsSeen(const PassContext& context, bool reflectionWork);
    ~OnlyWhereWaterIsSeen();
    OnlyWhereWaterIsSeen(const OnlyWhereWaterIsSeen&) = delete;
    OnlyWhereWaterIsSeen& operator=(const OnlyWhereWaterIsSeen&) = delete;
private:
    bool conditional_ = false;
};
bool mirroredPassActive(const FrameSetup& frame, Mirroring mirroring);
std::string variantName(const std::string& base, SurfaceOutput output, Mirroring mirroring);
const char* surfaceOutputName(SurfaceOutput output);
// Where a layout that rebuilds position from depth (compact) reads that depth: the depth-stencil
// target itself, for the readers that draw without it attached (views, the probe, compute) or
// test it read-only where the context allows that (the direct lighting: read-only depth); or
// DepthCopyPass's copy, for passes that write stencil while they read depth (the light volumes)
// and the mirrored lighting.
enum class DepthRead { FromTarget, FromCopy };
// Binds the G-buffer's colour targets and, where the layout rebuilds position from depth, the
// depth-stencil target to their units, for what reads the G-buffer outside a pass (the views, the
// probes); a pass gets them from its declarations (bindDeclaredInputs).
void bindGBufferInputs(const FrameTargets& targets);
// The colour targets a surface output draws into this frame: the G-buffer's stored ones (no
// Position where the layout rebuilds it from depth), Radiance (+ Final where the tone map is fused)
// or Reflection.
std::vector<Target> surfaceOutputTargets(const FrameSetup& frame, SurfaceOutput output,
                                         Mirroring mirroring = Mirroring::Direct);
// The G-buffer's colour targets this frame stores, and the depth a compact layout's position is
// rebuilt from: what a pass that reads the G-buffer samples.
std::vector<Access> gbufferSamples(const FrameSetup& frame, DepthRead depthRead);
// The uses of the depth-stencil target of a draw that tests depth (and writes it), and the stencil.
void appendDepthStencil(std::vector<Access>& accesses, std::initializer_list<Use> uses);

}  // namespace oasis
