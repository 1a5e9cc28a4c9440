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
// The depth of GL_READ_FRAMEBUFFER's depth-stencil attachment as floats, `out` w * h.
void readDepthFloats(int width, int height, float* out);
// The stencil of GL_READ_FRAMEBUFFER's depth-stencil attachment, `out` w * h bytes.
void readStencilBytes(int width, int height, uint8_t* out);

}  // namespace oasis
