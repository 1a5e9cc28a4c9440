// The G-buffer layouts: the one table of target formats. `--gbuffer NAME` picks a row.
#pragma once
#include <epoxy/gl.h>

#include <string>
#include <vector>

namespace oasis {

// The render targets of a frame. The G-buffer is the first four plus DepthStencil. Radiance and
// Reflection hold linear HDR light (the frame, and the mirrored scene seen in the water);
// Final is Radiance tone-mapped to 8 bits for display.
enum class Target { Albedo, Normal, Position, Info, DepthStencil, Radiance, Reflection, Final, Count };
const char* targetName(Target target);

struct TargetFormat {
    GLenum internalFormat;
    int bytesPerPixel;
};

struct GBufferLayout {
    std::string name;
    std::string description;
    TargetFormat albedo, normal, position, info;

    TargetFormat format(Target target) const;  // targets outside the G-buffer are the same in every layout
    int bytesPerPixel() const;                 // the four G-buffer colour targets plus depth-stencil
};

const std::vector<GBufferLayout>& gbufferLayouts();
const GBufferLayout* findGBufferLayout(const std::string& name);
const GBufferLayout& defaultGBufferLayout();
std::string gbufferLayoutNames();  // "full, standard" for help and error text

}  // namespace oasis
