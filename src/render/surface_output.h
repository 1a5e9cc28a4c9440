// Where a geometry pass sends its surfaces, and whether it draws the direct view or its mirror
// image in the water; shared by the passes and the GPU scene data they draw.
#pragma once

namespace oasis {

// Into the G-buffer, or shaded into Radiance.
enum class SurfaceOutput { GBuffer, Forward };
// The scene as seen directly, or its mirror image in the water (which goes to the Reflection
// target when shaded, and only where the stencil marks water).
enum class Mirroring { Direct, Mirrored };

}  // namespace oasis
