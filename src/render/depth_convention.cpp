// The depth convention table and the frame's clip-control scope.
#include "render/depth_convention.h"

namespace oasis {
namespace {

// D24S8 packs into 32 bits. D32F_S8 is counted as 8 bytes: drivers allocate 64 bits per pixel for
// it (Mesa's Z32_FLOAT_S8X24_UINT: a float, the stencil byte and 24 unused bits).
constexpr TargetFormat kDepth24Stencil8{GL_DEPTH24_STENCIL8, 4};
constexpr TargetFormat kDepth32FStencil8{GL_DEPTH32F_STENCIL8, 8};

const std::vector<DepthConvention> kConventions = {
    {"standard", "24-bit fixed-point depth, near 0 far 1, NDC z -1..1 (OpenGL's default)", DepthMapping::Standard,
     kDepth24Stencil8, GL_LESS, GL_LEQUAL, GL_GREATER, GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE, -1.0f, 1.0f, 1.0f},
    // A float's exponent spends its precision near 0, where 1/distance is small: the far field.
    {"reversed-z", "32-bit float depth, near 1 far 0 (glClipControl ZERO_TO_ONE, near and far swapped)",
     DepthMapping::Reversed, kDepth32FStencil8, GL_GREATER, GL_GEQUAL, GL_LESS, GL_LOWER_LEFT, GL_ZERO_TO_ONE, 1.0f, 0.0f,
     0.0f},
};

}  // namespace

const std::vector<DepthConvention>& depthConventions() { return kConventions; }

const DepthConvention* findDepthConvention(const std::string& name) {
    for (const DepthConvention& convention : kConventions)
        if (convention.name == name) return &convention;
    return nullptr;
}

const DepthConvention& standardDepthConvention() { return kConventions[0]; }

std::string depthConventionNames() {
    std::string names;
    for (const DepthConvention& convention : kConventions) names += (names.empty() ? "" : ", ") + convention.name;
    return names;
}

double depthStepAt(const DepthConvention& depth, double eyeDistance, double nearPlane, double farPlane) {
    if (depth.reversed()) return eyeDistance / 16777216.0;
    return eyeDistance * eyeDistance * (farPlane - nearPlane) / (farPlane * nearPlane * 16777215.0);
}

TargetFormat targetFormat(const GBufferLayout& layout, const DepthConvention& depth, Target target) {
    // The depth copy of the layouts that reconstruct position from depth has the depth's format.
    const FormatFrom from = targetDescriptor(target).format;
    if (from == FormatFrom::Depth || (from == FormatFrom::DepthCopy && layout.stores(target))) return depth.depthStencil;
    return layout.format(target);
}

int gbufferBytesPerPixel(const GBufferLayout& layout, const DepthConvention& depth) {
    int bytes = layout.bytesPerPixel();
    for (Target target : {Target::DepthStencil, Target::SceneDepth})
        bytes += targetFormat(layout, depth, target).bytesPerPixel - layout.format(target).bytesPerPixel;
    return bytes;
}

FrameClipControl::FrameClipControl(const DepthConvention& depth) {
    if (!depth.needsClipControl()) return;
    glClipControl(depth.clipOrigin, depth.clipDepthMode);
    set_ = true;
}

FrameClipControl::~FrameClipControl() {
    if (set_) glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
}

}  // namespace oasis
