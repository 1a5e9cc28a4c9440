// The frame's depth and stencil read back to the CPU on every context. glReadPixels reads them on
// desktop GL, and on OpenGL ES only with GL_NV_read_depth_stencil, which WebGL 2 and most ES drivers
// (ANGLE's among them) lack: there they are read by drawing (shaders/depth_stencil_read.frag) into
// a colour target that ES can read. Both ways give the same numbers: the depth as stored (a 24-bit
// unorm d / (2^24 - 1), or the float) and the stencil's 8 bits.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "render/frame_targets.h"
#include "render/shader_library.h"

namespace oasis {

// The region's depth (floats) or stencil (bytes) of a depth-stencil target of `targets`
// (DepthStencil, or the SceneDepth copy), rows bottom-up as GL keeps them; x, y in GL's window
// coordinates. `drawn`: by drawing, where the context's glReadPixels cannot read them
// (gl::Capabilities::depthStencilReadAvailable, given to the renderer as
// RendererCapabilities::depthStencilRead).
struct DepthStencilRead {
    Target target = Target::DepthStencil;
    int x = 0, y = 0, width = 0, height = 0;
    bool drawn = false;
    int divisor = 1;  // the target at 1/divisor of the frame (the reduced reflection's)
};
std::vector<float> readDepthRegion(ShaderLibrary& shaders, const FrameTargets& targets, const DepthStencilRead& read);
std::vector<uint8_t> readStencilRegion(ShaderLibrary& shaders, const FrameTargets& targets, const DepthStencilRead& read);
// The whole frame's DepthStencil.
inline DepthStencilRead wholeDepthStencil(const FrameTargets& targets, bool drawn) {
    return {Target::DepthStencil, 0, 0, targets.width(), targets.height(), drawn};
}

}  // namespace oasis
