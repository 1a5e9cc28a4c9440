// The G-buffer format table, the frame targets' descriptors, and what follows from them.
#include "render/gbuffer_layout.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "common/shared_constants.glsl"

namespace oasis {
namespace {

constexpr TargetFormat kRGBA8{GL_RGBA8, 4};
constexpr TargetFormat kRGBA16F{GL_RGBA16F, 8};
constexpr TargetFormat kRGBA32F{GL_RGBA32F, 16};
constexpr TargetFormat kRG16{GL_RG16, 4};
constexpr TargetFormat kRG8{GL_RG8, 2};
constexpr TargetFormat kNotStored{0, 0};
constexpr TargetFormat kDepth24Stencil8{GL_DEPTH24_STENCIL8, 4};
constexpr TargetFormat kFinalColour{GL_RGBA8, 4};
constexpr TargetFormat kLinearLight{GL_RGBA16F, 8};

// The frame's targets, one row each.
constexpr TargetDescriptor kTargetDescriptors[] = {
    {Target::Albedo, "albedo", "G-buffer albedo", FormatFrom::LayoutRow, &GBufferLayout::albedo, kNotStored},
    {Target::Normal, "normal", "G-buffer normal", FormatFrom::LayoutRow, &GBufferLayout::normal, kNotStored},
    {Target::Position, "position", "G-buffer position", FormatFrom::LayoutRow, &GBufferLayout::position, kNotStored},
    {Target::Info, "info", "G-buffer info", FormatFrom::LayoutRow, &GBufferLayout::info, kNotStored},
    {Target::DepthStencil, "depth-stencil", "G-buffer depth-stencil", FormatFrom::Depth, nullptr, kDepth24Stencil8},
    {Target::Radiance, "radiance", "Radiance", FormatFrom::Own, nullptr, kLinearLight},
    {Target::Reflection, "reflection", "Reflection", FormatFrom::Own, nullptr, kLinearLight},
    {Target::Final, "final", "Final", FormatFrom::Own, nullptr, kFinalColour},
    {Target::SceneDepth, "scene-depth", "SceneDepth copy", FormatFrom::DepthCopy, nullptr, kDepth24Stencil8},
};
static_assert(std::size(kTargetDescriptors) == size_t(Target::Count), "one row a target");

// Positions are stored relative to the camera, so 32-bit floats keep sub-millimetre precision
// near the viewer wherever the camera is; normals tolerate half floats (|n| error < 1e-3).
// Compact: 16-bit octahedral normals (about 5e-5 rad steps) beat half floats; the position comes
// back from a copy of depth (SceneDepth) with the depth format's error, which grows with distance.
const std::vector<GBufferLayout> kLayouts = {
    {"full", "32-bit float in every colour target: the reference", kRGBA32F, kRGBA32F, kRGBA32F, kRGBA32F,
     GBufferEncoding::AsIs},
    {"standard", "8-bit albedo and info, half-float normal, float position",
     kRGBA8, kRGBA16F, kRGBA32F, kRGBA8, GBufferEncoding::AsIs},
    {"compact", "8-bit albedo + specular intensity, 16-bit octahedral normal, 8-bit power + flags; "
     "position reconstructed from a copy of depth (the default)", kRGBA8, kRG16, kNotStored, kRG8, GBufferEncoding::Compact},
};

}  // namespace

const TargetDescriptor& targetDescriptor(Target target) {
    for (const TargetDescriptor& row : kTargetDescriptors)
        if (row.target == target) return row;
    static const TargetDescriptor none{Target::Count, "?", "?", FormatFrom::Own, nullptr, kNotStored};
    return none;
}

const char* targetName(Target target) { return targetDescriptor(target).name; }

bool GBufferLayout::needsNorm16Targets() const {
    // GL_RG16 is the table's only 16-bit unorm format.
    for (const TargetFormat& target : {albedo, normal, position, info})
        if (target.internalFormat == GL_RG16) return true;
    return false;
}

TargetFormat GBufferLayout::format(Target target) const {
    const TargetDescriptor& row = targetDescriptor(target);
    switch (row.format) {
        case FormatFrom::LayoutRow: return this->*row.row;
        case FormatFrom::DepthCopy: return positionFromDepth() ? row.own : kNotStored;
        default: return row.own;
    }
}

std::string GBufferLayout::program(const std::string& base) const { return base + gbufferEncodingSuffix(encoding); }

glm::vec4 GBufferLayout::clearedInfo() const {
    glm::vec4 info(0.0f);
    info[encoding == GBufferEncoding::Compact ? OASIS_COMPACT_INFO_FLAGS_CHANNEL : OASIS_INFO_FLAGS_CHANNEL] =
        float(OASIS_SURFACE_SKY) / 255.0f;
    return info;
}

glm::vec3 GBufferLayout::storedNormal(glm::vec4 texel) const {
    if (encoding == GBufferEncoding::Compact) return octahedralDecode(glm::vec2(texel) * 2.0f - 1.0f);
    return glm::vec3(texel);
}

unsigned GBufferLayout::storedFlags(glm::vec4 texel) const {
    int channel = encoding == GBufferEncoding::Compact ? OASIS_COMPACT_INFO_FLAGS_CHANNEL : OASIS_INFO_FLAGS_CHANNEL;
    return unsigned(std::lround(texel[channel] * 255.0f));
}

GBufferLayout::StoredSurface GBufferLayout::storedSurface(glm::dvec4 albedo, glm::dvec4 normal, glm::dvec4 info) const {
    const bool compact = encoding == GBufferEncoding::Compact;
    StoredSurface s;
    s.albedo = glm::dvec3(albedo);
    s.normal = compact ? octahedralDecode(glm::dvec2(normal) * 2.0 - 1.0) : glm::dvec3(normal);
    s.specularPower = std::round(info.r * 255.0);
    s.specularIntensity = compact ? albedo.a : info.g;
    s.flags = storedFlags(glm::vec4(info));  // the texels are floats as read back: exact in float
    return s;
}

const char* gbufferEncodingDefine(GBufferEncoding encoding) {
    return encoding == GBufferEncoding::Compact ? "GBUFFER_COMPACT" : "";
}

const char* gbufferEncodingSuffix(GBufferEncoding encoding) {
    return encoding == GBufferEncoding::Compact ? ".compact" : "";
}

glm::vec2 octahedralEncode(glm::vec3 n) {
    n /= std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z);
    glm::vec2 folded(n.x, n.z);
    if (n.y < 0.0f)  // the lower half folds over the diagonals
        folded = (1.0f - glm::abs(glm::vec2(n.z, n.x))) *
                 glm::vec2(n.x >= 0.0f ? 1.0f : -1.0f, n.z >= 0.0f ? 1.0f : -1.0f);
    return folded;
}

int GBufferLayout::bytesPerPixel() const {
    return albedo.bytesPerPixel + normal.bytesPerPixel + position.bytesPerPixel + info.bytesPerPixel +
           kDepth24Stencil8.bytesPerPixel + format(Target::SceneDepth).bytesPerPixel;
}

const std::vector<GBufferLayout>& gbufferLayouts() { return kLayouts; }

const GBufferLayout* findGBufferLayout(const std::string& name) {
    for (const GBufferLayout& layout : kLayouts)
        if (layout.name == name) return &layout;
    return nullptr;
}

// The default sits on the bench's time-against-error frontier (README, Speed against error).
const GBufferLayout& defaultGBufferLayout() { return *findGBufferLayout(kDefaultGBufferLayoutName); }
const GBufferLayout& norm16FallbackGBufferLayout() { return *findGBufferLayout("standard"); }

std::string gbufferLayoutNames() {
    std::string names;
    for (const GBufferLayout& layout : kLayouts) names += (names.empty() ? "" : ", ") + layout.name;
    return names;
}

}  // namespace oasis
