// What the renderer's last frame left, read back for tests and tools: the Display image, a colour
// target, the surfaces' positions, depth, stencil and the water's bounds; and an image put into
// Display for Renderer::present() to show. Each read is a stall.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "frame/renderer.h"
#include "render/image.h"

namespace oasis {

// Throws std::logic_error when the frame's plan lent `target`'s memory to a target used after it
// (FrameTargets::holderAfterFrame): its values are gone; the frame's sink (views().setSink) must
// name what is read after it. Every read of a target below asks this first.
void requireHeldAfterFrame(const FrameTargets& targets, Target target);
// The Display target, top row first.
Image readDisplay(const Renderer& renderer);
// Puts an image of the frame's size (top row first) into Display, e.g. a view's values mapped by
// the view controls on the CPU, for present() to show; throws std::invalid_argument for another size.
void showImage(Renderer& renderer, const Image& image);
// A colour target as RGBA floats, bottom row first (GL order); throws std::invalid_argument for a
// target the layout does not store. Radiance is read with the water laid on (ensureRadiance).
std::vector<float> readTarget(Renderer& renderer, Target target);
// The G-buffer's surface positions as lighting reads them (stored, or reconstructed from the
// depth-stencil target's depth, refilled where the water's depth covers the mirrored scene:
// after a whole frame, the G-buffer's own surfaces):
// camera-relative xyz, w 1; 0 where the SKY flag is set. RGBA floats, bottom row first.
std::vector<float> readSurfacePositions(Renderer& renderer);
std::vector<float> readDepth(const Renderer& renderer);
std::vector<uint8_t> readStencil(const Renderer& renderer);
// The frame's uniform block and its point lights as the driver holds them, read back from their
// buffers (the light list's length from its count buffer): what the shaders read, not the CPU's copy.
FrameData readFrameBlock(const Renderer& renderer);
std::vector<PointLight> readLightList(const Renderer& renderer);
// The last frame's rectangle of visible water in pixels (x0, y0, x1, y1 inclusive, rows bottom-up;
// empty: x0 > x1) as the GPU recorded it (RenderPaths::waterBoundsAvailable; empty without).
glm::ivec4 readWaterBounds(const Renderer& renderer);

}  // namespace oasis
