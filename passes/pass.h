// A render pass: it names itself, declares the targets it reads and writes, and executes a short
// list of GL calls inside a KHR_debug group of its name. A pipeline is an ordered list of passes.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "gl/objects.h"
#include "render/frame_setup.h"
#include "render/frame_targets.h"
#include "render/scene_geometry.h"
#include "render/shader_library.h"

namespace oasis {

// What every pass may use while it executes.
struct PassContext {
    const FrameTargets& targets;
    ShaderLibrary& shaders;
    const SceneGeometry& geometry;
    const FrameSetup& frame;
};

// Where a geometry pass sends its surfaces: into the G-buffer, or shaded into Final.
enum class SurfaceOutput { GBuffer, Forward };

class Pass {
public:
    virtual ~Pass() = default;
    virtual std::string name() const = 0;
    virtual std::vector<Target> reads() const = 0;
    virtual std::vector<Target> writes() const = 0;

    void run(PassContext& context) {
        gl::DebugGroup group(name().c_str());
        execute(context);
    }

protected:
    virtual void execute(PassContext& context) = 0;
};

// The stencil value each kind of surface writes, shown by the stencil debug view.
enum StencilMark : int { kStencilNothing = 0, kStencilTerrain = 1 };

// Binds the framebuffer a surface output draws into and sets the viewport to the whole frame.
void bindSurfaceOutput(const FrameTargets& targets, SurfaceOutput output);
const char* surfaceOutputName(SurfaceOutput output);
// Binds the four G-buffer colour targets to their texture units for a pass that reads them.
void bindGBufferInputs(const FrameTargets& targets);
std::vector<Target> surfaceOutputTargets(SurfaceOutput output);

}  // namespace oasis
