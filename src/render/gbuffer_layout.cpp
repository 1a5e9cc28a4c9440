// The G-buffer format table and what follows from it.
#include "render/gbuffer_layout.h"

namespace oasis {
namespace {

constexpr TargetFormat kRGBA8{GL_RGBA8, 4};
constexpr TargetFormat kRGBA16F{GL_RGBA16F, 8};
constexpr TargetFormat kRGBA32F{GL_RGBA32F, 16};
constexpr TargetFormat kDepth24Stencil8{GL_DEPTH24_STENCIL8, 4};
constexpr TargetFormat kFinalColour{GL_RGBA8, 4};
constexpr TargetFormat kLinearLight{GL_RGBA16F, 8};

// Positions are stored relative to the camera, so 32-bit floats keep sub-millimetre precision
// near the viewer wherever the camera is; normals tolerate half floats (|n| error < 1e-3).
const std::vector<GBufferLayout> kLayouts = {
    {"full", "32-bit float in every colour target: the reference", kRGBA32F, kRGBA32F, kRGBA32F, kRGBA32F},
    {"standard", "8-bit albedo and info, half-float normal, float position (the default)",
     kRGBA8, kRGBA16F, kRGBA32F, kRGBA8},
};

}  // namespace

const char* targetName(Target target) {
    switch (target) {
        case Target::Albedo: return "albedo";
        case Target::Normal: return "normal";
        case Target::Position: return "position";
        case Target::Info: return "info";
        case Target::DepthStencil: return "depth-stencil";
        case Target::Radiance: return "radiance";
        case Target::Reflection: return "reflection";
        case Target::Final: return "final";
        case Target::Count: break;
    }
    return "?";
}

TargetFormat GBufferLayout::format(Target target) const {
    switch (target) {
        case Target::Albedo: return albedo;
        case Target::Normal: return normal;
        case Target::Position: return position;
        case Target::Info: return info;
        case Target::DepthStencil: return kDepth24Stencil8;
        case Target::Radiance:
        case Target::Reflection: return kLinearLight;
        default: return kFinalColour;
    }
}

int GBufferLayout::bytesPerPixel() const {
    return albedo.bytesPerPixel + normal.bytesPerPixel + position.bytesPerPixel + info.bytesPerPixel +
           kDepth24Stencil8.bytesPerPixel;
}

const std::vector<GBufferLayout>& gbufferLayouts() { return kLayouts; }

const GBufferLayout* findGBufferLayout(const std::string& name) {
    for (const GBufferLayout& layout : kLayouts)
        if (layout.name == name) return &layout;
    return nullptr;
}

const GBufferLayout& defaultGBufferLayout() { return kLayouts[1]; }

std::string gbufferLayoutNames() {
    std::string names;
    for (const GBufferLayout& layout : kLayouts) names += (names.empty() ? "" : ", ") + layout.name;
    return names;
}

}  // namespace oasis
