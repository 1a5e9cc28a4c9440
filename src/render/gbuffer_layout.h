// The G-buffer layouts: the one table of target formats and encodings. `--gbuffer NAME` picks a row.
// The frame's targets described (TargetDescriptor): their names, labels and where their formats come from.
#pragma once
#include <epoxy/gl.h>

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace oasis {

// The render targets of a frame. The G-buffer is the first four plus DepthStencil. Radiance and
// Reflection hold linear HDR light (the frame, and the mirrored scene seen in the water);
// Final is Radiance tone-mapped to 8 bits for display.
// SceneDepth: a copy of depth for the layouts that reconstruct position from it (DepthCopyPass).
enum class Target { Albedo, Normal, Position, Info, DepthStencil, Radiance, Reflection, Final, SceneDepth, Count };
const char* targetName(Target target);

struct TargetFormat {
    GLenum internalFormat;  // 0: the layout does not store this target
    int bytesPerPixel;
};

// How the surface is written into the targets (shaders/common/gbuffer.glsl).
enum class GBufferEncoding {
    AsIs,     // albedo rgb, normal xyz, camera-relative position xyz (w 1), info (power, intensity, flags)
    Compact,  // albedo rgb + specular intensity, octahedral normal in rg, info (power, flags);
              // no position: reconstructed from depth
};

struct GBufferLayout {
    std::string name;
    std::string description;
    TargetFormat albedo, normal, position, info;
    GBufferEncoding encoding;

    TargetFormat format(Target target) const;  // targets outside the G-buffer are the same in every layout
    int bytesPerPixel() const;                 // the G-buffer colour targets it stores, depth-stencil, SceneDepth
    bool stores(Target target) const { return format(target).internalFormat != 0; }
    bool positionFromDepth() const { return position.internalFormat == 0; }
    // Whether a colour target is 16-bit unorm (the compact layout's RG16 normal): renderable on
    // OpenGL ES only with EXT_texture_norm16 (the renderer falls back to standard without it).
    bool needsNorm16Targets() const;
    // The shader program of a G-buffer reader or writer for this layout: "lighting" ->
    // "lighting.compact" where the encoding needs its own #define (shader_variants.cpp).
    std::string program(const std::string& base) const;
    // The value the clear leaves in the info target (the SKY flag in the layout's flags channel).
    glm::vec4 clearedInfo() const;
    // Reads the CPU copy of a texel back (readTarget's floats): the unit normal, the flags.
    glm::vec3 storedNormal(glm::vec4 normalTexel) const;
    unsigned storedFlags(glm::vec4 infoTexel) const;
    // A surface's texels decoded as common/gbuffer.glsl's readGBuffer decodes them, in double (the
    // shading oracle's precision); its position aside: stored, or rebuilt from depth.
    struct StoredSurface {
        glm::dvec3 albedo{0.0}, normal{0.0};
        double specularPower = 0.0, specularIntensity = 0.0;
        unsigned flags = 0;
    };
    StoredSurface storedSurface(glm::dvec4 albedoTexel, glm::dvec4 normalTexel, glm::dvec4 infoTexel) const;
};

// Where a frame target's format comes from: its row of the G-buffer layout, the depth convention
// (the depth-stencil target; its copy where the layout rebuilds position from depth), or a format
// of its own, the same in every layout.
enum class FormatFrom { LayoutRow, Depth, DepthCopy, Own };
// A frame target described: one row of the one table of targets (gbuffer_layout.cpp), from which
// its name, its texture's format and its label come; its size is a scale of the frame's (the
// resource's, render/frame_resource.h).
struct TargetDescriptor {
    Target target;
    const char* name;   // as the CLI, the views and render --graph name it
    const char* label;  // as capture tools list its texture, the layout (and depth) whose format it has after it
    FormatFrom format;
    TargetFormat GBufferLayout::*row;  // with FormatFrom::LayoutRow
    TargetFormat own;                  // otherwise (the standard depth's where the depth convention decides)
};
const TargetDescriptor& targetDescriptor(Target target);

// The #define and program-name suffix of an encoding ("" for AsIs: its shaders are the base ones).
const char* gbufferEncodingDefine(GBufferEncoding encoding);
const char* gbufferEncodingSuffix(GBufferEncoding encoding);

const std::vector<GBufferLayout>& gbufferLayouts();
const GBufferLayout* findGBufferLayout(const std::string& name);
inline constexpr const char* kDefaultGBufferLayoutName = "compact";
const GBufferLayout& defaultGBufferLayout();
// The layout the renderer draws where the one asked for needs 16-bit unorm targets the context
// cannot draw into: "standard" (half-float normal, float position).
const GBufferLayout& norm16FallbackGBufferLayout();
std::string gbufferLayoutNames();  // "full, standard, compact" for help and error text

// Octahedral unit-vector encoding (as shaders/common/gbuffer.glsl): [-1,1]^2 and back, the decoding
// in float or double.
glm::vec2 octahedralEncode(glm::vec3 unit);
template <typename T, glm::qualifier Q>
glm::vec<3, T, Q> octahedralDecode(glm::vec<2, T, Q> e) {
    glm::vec<3, T, Q> n(e.x, T(1) - glm::abs(e.x) - glm::abs(e.y), e.y);
    T fold = glm::max(-n.y, T(0));
    n.x += n.x >= T(0) ? -fold : fold;
    n.z += n.z >= T(0) ? -fold : fold;
    return glm::normalize(n);
}

}  // namespace oasis
