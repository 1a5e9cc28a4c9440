// Reading the bound read framebuffer back to the CPU on both APIs. Desktop GL converts any colour
// buffer to floats and reads depth as floats and stencil as bytes by itself; OpenGL ES reads a
// unorm buffer only as bytes (or shorts, 16-bit), depth and stencil only through
// GL_NV_read_depth_stencil's packed formats. These pick the read the context allows and convert
// as desktop GL does (unorm c / (2^bits - 1), 24-bit depth d / (2^24 - 1)).
#pragma once
#include <cstdint>

#include <epoxy/gl.h>

namespace oasis {

// RGBA floats of the read buffer (GL_READ_FRAMEBUFFER's current glReadBuffer), `out` 4 * w * h.
void readColourFloats(int width, int height, float* out);
// The depth of GL_READ_FRAMEBUFFER's depth-stencil attachment in the region as floats, `out` w * h;
// the stencil, `out` w * h bytes. On ES only with GL_NV_read_depth_stencil: read them through
// render/depth_stencil_readback.h, which draws them where the context cannot read them.
void readDepthFloats(int x, int y, int width, int height, float* out);
void readStencilBytes(int x, int y, int width, int height, uint8_t* out);

}  // namespace oasis
