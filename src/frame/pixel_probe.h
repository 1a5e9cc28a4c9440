// The pixel probe: every target's texel at one pixel of the last frame, as stored (bytes, half
// floats or floats, per the layout's formats) and decoded (the G-buffer through the same GLSL the
// lighting pass reads it with). `oasis probe` prints it; the window's inspector shows it.
#pragma once
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace oasis {

class Renderer;

// One target's texel as the driver stores it.
struct StoredTexel {
    std::string target;            // "albedo", "depth-stencil", ...
    std::string format;            // "RGBA8", "RG16", "RGBA16F", "D24S8", ...
    std::string storedAs;          // "bytes", "16-bit unorm", "half floats", "floats", "24-bit depth + 8-bit stencil"
    std::vector<double> values;    // the stored numbers, channel by channel
};

class FrameTargets;
class ShaderLibrary;
enum class Target;
// One target's texel at GL pixel (glX, glY), bottom row 0, as stored: any time, mid-frame too.
// `drawDepthStencil`: depth and stencil are drawn out with `shaders` to be read, where glReadPixels
// cannot read them (RendererCapabilities::depthStencilRead, render/depth_stencil_readback.h).
// `divisor`: the target at 1/divisor of the frame (the reduced reflection's), (glX, glY) in it.
StoredTexel readStoredTexel(ShaderLibrary& shaders, const FrameTargets& targets, Target target, int glX, int glY,
                            bool drawDepthStencil, int divisor = 1);

struct PixelProbe {
    int x = 0, y = 0;              // as asked: 0,0 is the top-left pixel (as in the PNGs)
    std::string pipeline, layout, depthConvention;
    std::vector<StoredTexel> stored;

    // The G-buffer surface, decoded on the GPU (common/gbuffer.glsl's readGBuffer).
    bool sky = false;
    glm::vec3 albedo{0.0f};        // linear reflectance
    glm::vec3 albedoSrgb{0.0f};    // the same, sRGB-encoded (0..1)
    glm::vec3 normal{0.0f};
    float normalLength = 0.0f;
    glm::vec3 relativePosition{0.0f};  // camera-relative, as stored or reconstructed (mirror image where reflected)
    glm::dvec3 worldPosition{0.0};     // of the surface itself (a reflection's real position)
    float eyeDistance = 0.0f;          // |relativePosition|
    float specularPower = 0.0f, specularIntensity = 0.0f;
    unsigned flags = 0;
    std::vector<std::string> flagNames;  // "SKY", "REFLECTED", "PLANT"
    double sceneDepth = -1.0;            // compact: the depth the position was rebuilt from; else -1

    // The depth-stencil target.
    double depth = 0.0;            // window depth as stored (0..1)
    double depthEyeDistance = 0.0; // along the view axis, under the depth convention
    bool depthCleared = false;     // the clear value: nothing drawn
    int stencil = 0;
    std::string stencilMeaning;

    glm::vec4 radiance{0.0f}, reflection{0.0f};  // linear HDR, as stored (RGBA16F)
    // How this frame drew the reflection Reflection holds: "full", "half" or "quarter"
    // (--reflection-resolution), the size of the targets the mirrored scene was drawn into (a reduced
    // one is upsampled bilinearly into Reflection, so its value here blends up to four of their
    // texels); "" where no mirrored scene was drawn (reflections off, the camera under the water).
    std::string reflectionResolution;
    int reflectionWidth = 0, reflectionHeight = 0;
    glm::ivec4 final{0};                         // the displayed 8-bit colour
    int lightsReaching = 0, lightsInList = 0;    // point lights whose sphere holds the surface
    // The sun's shadow as lighting reads it (common/shadows.glsl): 0 shadowed .. 1 lit, the cascade
    // that answered (-1: none, shadows off, the sun down or the sky), and n.l towards the sun.
    float shadowLit = 1.0f, sunFacing = 0.0f;
    int shadowCascade = -1;
    std::string waterScene;  // on water pixels: which scene the G-buffer holds there and why; else ""

    // The layout's encoding error here against `full` (not for full itself; NaN: no common surface).
    bool hasEncodingError = false;
    float normalErrorDegrees = 0.0f, positionErrorUnits = 0.0f, positionErrorSteps = 0.0f;
};

struct EncodingError;
// Fills the probe's encoding-error fields from a measurement of the same frame and size.
void addEncodingError(PixelProbe& probe, const EncodingError& error);

// Probes pixel (x, y) of the last frame (0,0 top-left). A forward frame's G-buffer is filled first
// by the deferred geometry passes, as the G-buffer views do. Throws std::out_of_range outside the frame.
PixelProbe probePixel(Renderer& renderer, int x, int y);

std::string probeText(const PixelProbe& probe);  // several lines, for people
std::string probeJson(const PixelProbe& probe);  // one JSON object

}  // namespace oasis
