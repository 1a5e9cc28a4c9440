// The pixel probe: read every target's texel at one pixel as stored, and decode the G-buffer there
// on the GPU (shaders/probe.frag) into a small float target, one quantity per texel.
#include "frame/pixel_probe.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "common/shared_constants.glsl"
#include "frame/encoding_error.h"
#include "frame/renderer.h"
#include "passes/pass.h"
#include "render/depth_stencil_readback.h"
#include "render/float_readback.h"
#include "render/texture_units.h"

namespace oasis {
namespace {

// How glReadPixels returns a texel of each format oasis allocates, unchanged.
struct ReadFormat {
    GLenum internalFormat;
    const char* name;
    GLenum format, type;
    int channels;
    const char* storedAs;
};

constexpr ReadFormat kReadFormats[] = {
    {GL_RGBA8, "RGBA8", GL_RGBA, GL_UNSIGNED_BYTE, 4, "bytes"},
    {GL_RG8, "RG8", GL_RG, GL_UNSIGNED_BYTE, 2, "bytes"},
    {GL_RG16, "RG16", GL_RG, GL_UNSIGNED_SHORT, 2, "16-bit unorm"},
    {GL_RGBA16F, "RGBA16F", GL_RGBA, GL_HALF_FLOAT, 4, "half floats"},
    {GL_RGBA32F, "RGBA32F", GL_RGBA, GL_FLOAT, 4, "floats"},
    {GL_DEPTH24_STENCIL8, "D24S8", GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, 1, "24-bit depth, 8-bit stencil"},
    {GL_DEPTH32F_STENCIL8, "D32F_S8", GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, 2,
     "float depth, 8-bit stencil"},
};

const ReadFormat& readFormatOf(GLenum internalFormat) {
    for (const ReadFormat& format : kReadFormats)
        if (format.internalFormat == internalFormat) return format;
    throw std::logic_error("the probe cannot read internal format " + std::to_string(internalFormat));
}

// The framebuffer and attachment a target can be read from.
std::pair<GLuint, GLenum> readSource(const FrameTargets& targets, Target target, int divisor) {
    switch (target) {
        case Target::DepthStencil:
        case Target::SceneDepth: return {targets.framebuffer({}, target, divisor), GL_NONE};
        default: return {targets.framebuffer({target}, std::nullopt, divisor), GL_COLOR_ATTACHMENT0};
    }
}

}  // namespace

StoredTexel readStoredTexel(ShaderLibrary& shaders, const FrameTargets& targets, Target target, int glX, int glY,
                            bool drawDepthStencil, int divisor) {
    const ReadFormat& format = readFormatOf(targetFormat(targets.layout(), targets.depth(), target).internalFormat);
    if (format.format == GL_DEPTH_STENCIL && drawDepthStencil) {
        // OpenGL ES without GL_NV_read_depth_stencil (WebGL 2): the depth and stencil drawn into
        // colour targets (render/depth_stencil_readback.h), given as the packed read gives them.
        DepthStencilRead read{target, glX, glY, 1, 1, true, divisor};
        double depth = readDepthRegion(shaders, targets, read)[0];
        double stencil = readStencilRegion(shaders, targets, read)[0];
        if (format.type == GL_UNSIGNED_INT_24_8) depth = std::round(depth * 16777215.0);  // the 24-bit unorm
        return {targetName(target), format.name, format.storedAs, {depth, stencil}};
    }
    auto [framebuffer, attachment] = readSource(targets, target, divisor);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    if (attachment != GL_NONE) glReadBuffer(attachment);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    StoredTexel texel{targetName(target), format.name, format.storedAs, {}};
    uint32_t words[4] = {};
    // OpenGL ES reads colour buffers as RGBA only (RG8 as RGBA bytes, RG16 as RGBA shorts with
    // EXT_texture_norm16) and half floats as floats: the same values, the first `channels` kept.
    GLenum readFormat = format.format, readType = format.type;
    if (!epoxy_is_desktop_gl() && attachment != GL_NONE) {
        readFormat = GL_RGBA;
        if (readType == GL_HALF_FLOAT) readType = GL_FLOAT;
    }
    glReadPixels(glX, glY, 1, 1, readFormat, readType, words);
    const auto* bytes = reinterpret_cast<const uint8_t*>(words);
    const auto* shorts = reinterpret_cast<const uint16_t*>(words);
    const auto* floats = reinterpret_cast<const float*>(words);
    for (int c = 0; c < format.channels; ++c) {
        switch (readType) {
            case GL_UNSIGNED_BYTE: texel.values.push_back(bytes[c]); break;
            case GL_UNSIGNED_SHORT: texel.values.push_back(shorts[c]); break;
            case GL_HALF_FLOAT: texel.values.push_back(glm::unpackHalf1x16(shorts[c])); break;
            case GL_FLOAT: texel.values.push_back(floats[c]); break;
            case GL_UNSIGNED_INT_24_8:  // depth in the high 24 bits, stencil in the low 8
                texel.values = {double(words[0] >> 8), double(words[0] & 0xffu)};
                break;
            case GL_FLOAT_32_UNSIGNED_INT_24_8_REV:  // a float, then the stencil in the low byte
                texel.values = {double(floats[0]), double(words[1] & 0xffu)};
                break;
        }
    }
    if (attachment != GL_NONE) glReadBuffer(GL_COLOR_ATTACHMENT0);
    return texel;
}

namespace {

// What each stencil value means (passes/pass.h StencilMark; bit 0x80 is a light volume's mark,
// which each light's own draw resets, so a finished frame never holds it).
std::string stencilMeaning(int value) {
    std::string meaning;
    switch (value & 0x7f) {
        case kStencilNothing: meaning = "nothing drawn (sky)"; break;
        case kStencilTerrain: meaning = "terrain"; break;
        case kStencilWater: meaning = "water"; break;
        case kStencilVegetation: meaning = "plant"; break;
        default: meaning = "unknown mark " + std::to_string(value & 0x7f); break;
    }
    if (value & 0x80) meaning += " + a light volume's mark (0x80)";
    return meaning;
}

std::vector<std::string> flagNames(unsigned flags) {
    std::vector<std::string> names;
    if (flags & OASIS_SURFACE_SKY) names.push_back("SKY");
    if (flags & OASIS_SURFACE_REFLECTED) names.push_back("REFLECTED");
    if (flags & OASIS_SURFACE_PLANT) names.push_back("PLANT");
    return names;
}

double srgbEncode(double linear) {
    linear = std::clamp(linear, 0.0, 1.0);
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

// Which scene the G-buffer and depth hold at a water pixel, and why (frame/view_fill.h).
std::string waterSceneAt(const PixelProbe& probe, const Renderer& renderer) {
    if ((probe.stencil & 0x7f) != kStencilWater) return {};
    const ViewScene& shown = renderer.views().scene();
    std::string text = shown.description;
    if (shown.scene == WaterScene::Mirrored)
        text += probe.flags & OASIS_SURFACE_REFLECTED ? ": a mirrored surface (REFLECTED flag)"
                                                      : ": no mirrored surface landed here (the water reflects the sky)";
    if (!shown.reason.empty()) text += "; " + shown.reason;
    else if (shown.scene) text += std::string("; --water-scene ") + waterSceneName(*shown.scene) + " (the other: " +
                                  (*shown.scene == WaterScene::Direct ? "mirrored" : "direct") + ")";
    return text;
}

// Texels no pass of the frame wrote hold whatever the memory held (an earlier frame's values, NaNs
// on zink): nothing clears the G-buffer's colour targets where no surface was drawn (the sky; Info
// too in the compact layout, which tells the sky by depth) nor Reflection outside the water. The
// probe shows them as the clear used to leave them: zeros, Info's SKY flag.
void showUnwrittenAsCleared(PixelProbe& probe, const GBufferLayout& layout, bool reflectionsActive) {
    bool reflectionWritten = reflectionsActive && (probe.stencil & 0x7f) == kStencilWater;
    for (StoredTexel& texel : probe.stored) {
        bool colour = texel.target == targetName(Target::Albedo) || texel.target == targetName(Target::Normal) ||
                      texel.target == targetName(Target::Position);
        bool info = texel.target == targetName(Target::Info) && layout.positionFromDepth();
        bool unwritten = ((colour || info) && probe.sky) ||
                         (texel.target == targetName(Target::Reflection) && !reflectionWritten);
        if (!unwritten) continue;
        std::fill(texel.values.begin(), texel.values.end(), 0.0);
        if (info)  // the compact layout's info is bytes
            for (size_t c = 0; c < texel.values.size(); ++c) texel.values[c] = std::round(layout.clearedInfo()[int(c)] * 255.0f);
    }
    if (!reflectionWritten) probe.reflection = glm::vec4(0.0f);
}

// The GPU half: shaders/probe.frag writes its slots into an 8x1 float target.
constexpr int kProbeSlots = 8;

std::array<glm::vec4, kProbeSlots> decodeOnGpu(Renderer& renderer, int glX, int glY) {
    const FrameTargets& targets = renderer.targets();
    FloatReadback values;
    values.bindForDrawing(kProbeSlots, 1);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    bindGBufferInputs(targets);
    renderer.parts().shadowMaps.bind();
    glActiveTexture(GL_TEXTURE0 + kUnitProbeDepthStencil);
    glBindTexture(GL_TEXTURE_2D, targets.texture(Target::DepthStencil));
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
    GLuint program = renderer.parts().shaders.program(targets.layout().program("probe.pixel"));
    glUseProgram(program);
    glUniform2i(glGetUniformLocation(program, "probePixel"), glX, glY);
    renderer.parts().geometry.drawFullscreenTriangle();
    std::vector<float> read = values.read();
    std::array<glm::vec4, kProbeSlots> slots{};
    for (int s = 0; s < kProbeSlots; ++s) slots[size_t(s)] = glm::vec4(read[s * 4], read[s * 4 + 1], read[s * 4 + 2], read[s * 4 + 3]);
    glActiveTexture(GL_TEXTURE0 + kUnitProbeDepthStencil);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    return slots;
}

}  // namespace

PixelProbe probePixel(Renderer& renderer, int x, int y) {
    const FrameTargets& targets = renderer.targets();
    if (x < 0 || y < 0 || x >= targets.width() || y >= targets.height())
        throw std::out_of_range("pixel " + std::to_string(x) + "," + std::to_string(y) + " is outside the " +
                                std::to_string(targets.width()) + "x" + std::to_string(targets.height()) + " frame");
    renderer.views().ensureGBuffer();
    int glX = x, glY = targets.height() - 1 - y;
    PixelProbe probe;
    probe.x = x;
    probe.y = y;
    probe.pipeline = pipelineName(renderer.pipeline());
    probe.layout = targets.layout().name;
    probe.depthConvention = targets.depth().name;
    // The depth copy is not listed: it is made only for the passes that read depth while testing
    // against it (light volumes, the reflection's lighting), so it need not hold this pixel's depth.
    for (int t = 0; t < int(Target::Count); ++t)
        if (Target(t) != Target::SceneDepth && targets.layout().stores(Target(t)))
            probe.stored.push_back(readStoredTexel(renderer.parts().shaders, targets, Target(t), glX, glY,
                                                   !renderer.paths().capabilities.depthStencilRead.available));

    std::array<glm::vec4, kProbeSlots> slot = decodeOnGpu(renderer, glX, glY);
    probe.albedo = glm::vec3(slot[0]);
    probe.albedoSrgb = glm::vec3(srgbEncode(slot[0].r), srgbEncode(slot[0].g), srgbEncode(slot[0].b));
    probe.normal = glm::vec3(slot[1]);
    probe.normalLength = slot[1].w;
    probe.relativePosition = glm::vec3(slot[2]);
    probe.eyeDistance = slot[2].w;
    probe.specularPower = slot[3].x;
    probe.specularIntensity = slot[3].y;
    probe.flags = unsigned(std::lround(slot[3].z));
    probe.flagNames = flagNames(probe.flags);
    probe.sky = slot[3].w > 0.5f;
    probe.depthEyeDistance = slot[4].y;
    probe.depthCleared = slot[4].z > 0.5f;
    if (targets.layout().positionFromDepth()) probe.sceneDepth = slot[6].x;
    probe.lightsReaching = int(std::lround(slot[5].x));
    probe.lightsInList = int(std::lround(slot[5].y));
    probe.shadowLit = slot[7].x;
    probe.shadowCascade = int(std::lround(slot[7].y));
    probe.sunFacing = slot[7].z;
    // The surface's own world position: a reflection is stored as its mirror image.
    glm::dvec3 camera = renderer.lastFrame().setup.view.pose.position;
    glm::dvec3 relative = glm::dvec3(probe.relativePosition);
    if (probe.flags & OASIS_SURFACE_REFLECTED) relative.y = double(slot[5].z);
    probe.worldPosition = probe.sky ? glm::dvec3(0.0) : camera + relative;

    for (const StoredTexel& texel : probe.stored) {
        if (texel.target == targetName(Target::DepthStencil)) {
            // The stored depth exactly: a 24-bit unorm or the float itself.
            probe.depth = texel.format == "D24S8" ? texel.values[0] / 16777215.0 : texel.values[0];
            probe.stencil = int(texel.values[1]);
        }
        if (texel.target == targetName(Target::Radiance))
            probe.radiance = glm::vec4(texel.values[0], texel.values[1], texel.values[2], texel.values[3]);
        if (texel.target == targetName(Target::Reflection))
            probe.reflection = glm::vec4(texel.values[0], texel.values[1], texel.values[2], texel.values[3]);
        if (texel.target == targetName(Target::Final))
            probe.final = glm::ivec4(texel.values[0], texel.values[1], texel.values[2], texel.values[3]);
    }
    showUnwrittenAsCleared(probe, targets.layout(), renderer.lastFrame().setup.reflectionsActive);
    probe.stencilMeaning = stencilMeaning(probe.stencil);
    probe.waterScene = waterSceneAt(probe, renderer);
    const FrameSetup& frame = renderer.lastFrame().setup;
    if (frame.reflectionsActive) {
        const int divisor = frame.reflectionDivisor;
        probe.reflectionResolution = reflectionResolutionName(divisor);
        probe.reflectionWidth = (targets.width() + divisor - 1) / divisor;
        probe.reflectionHeight = (targets.height() + divisor - 1) / divisor;
    }
    return probe;
}

void addEncodingError(PixelProbe& probe, const EncodingError& error) {
    if (probe.x >= error.width || probe.y >= error.height) return;
    size_t i = size_t(error.height - 1 - probe.y) * size_t(error.width) + size_t(probe.x);
    probe.hasEncodingError = true;
    probe.normalErrorDegrees = error.normalDegrees[i];
    probe.positionErrorUnits = error.positionUnits[i];
    probe.positionErrorSteps = error.positionSteps[i];
}

namespace {

// JSON has no NaN or infinity: those become null there (and read "nan", "inf" in the text).
bool gJsonNumbers = false;

std::string numbers(const std::vector<double>& values, const char* format) {
    std::string text;
    char number[64];
    for (size_t i = 0; i < values.size(); ++i) {
        if (gJsonNumbers && !std::isfinite(values[i])) std::snprintf(number, sizeof(number), "null");
        else std::snprintf(number, sizeof(number), format, values[i]);
        text += (i ? ", " : "") + std::string(number);
    }
    return text;
}

std::string vec(glm::dvec3 v, const char* format = "%.6g") { return numbers({v.x, v.y, v.z}, format); }
std::string vec(glm::dvec4 v, const char* format = "%.6g") { return numbers({v.x, v.y, v.z, v.w}, format); }

std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text) out += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
    return out + "\"";
}

std::string joined(const std::vector<std::string>& names, const char* separator, bool quote) {
    std::string text;
    for (size_t i = 0; i < names.size(); ++i) text += (i ? separator : "") + (quote ? quoted(names[i]) : names[i]);
    return text;
}

}  // namespace

std::string probeText(const PixelProbe& p) {
    std::string text;
    char line[512];
    auto add = [&](const char* format, auto... values) {
        std::snprintf(line, sizeof(line), format, values...);
        text += line;
    };
    add("pixel %d,%d (from the top left) of the %s frame, G-buffer '%s', depth %s\n", p.x, p.y, p.pipeline.c_str(),
        p.layout.c_str(), p.depthConvention.c_str());
    text += "stored:\n";
    for (const StoredTexel& texel : p.stored)
        add("  %-14s %-8s %s (%s)\n", texel.target.c_str(), texel.format.c_str(),
            numbers(texel.values, "%.9g").c_str(), texel.storedAs.c_str());
    text += "decoded (the G-buffer as lighting reads it):\n";
    if (p.sky) {
        text += "  sky: nothing drawn (SKY flag)\n";
    } else {
        add("  albedo         linear %s, sRGB %s\n", vec(glm::dvec3(p.albedo)).c_str(), vec(glm::dvec3(p.albedoSrgb)).c_str());
        add("  normal         %s, length %.6g\n", vec(glm::dvec3(p.normal)).c_str(), double(p.normalLength));
        add("  position       camera-relative %s, world %s, eye distance |p| %.6g\n",
            vec(glm::dvec3(p.relativePosition)).c_str(), vec(p.worldPosition, "%.9g").c_str(), double(p.eyeDistance));
        if (p.sceneDepth >= 0.0) add("                 rebuilt from depth %.9g\n", p.sceneDepth);
        add("  info           specular power %g, intensity %.6g, flags %u (%s)\n", double(p.specularPower),
            double(p.specularIntensity), p.flags, p.flagNames.empty() ? "none" : joined(p.flagNames, ", ", false).c_str());
        add("  lights         %d of %d point lights reach the surface\n", p.lightsReaching, p.lightsInList);
        if (p.shadowCascade >= 0)
            add("  shadow         lit fraction %.4g from sun cascade %d (n.l %.4g)\n", double(p.shadowLit),
                p.shadowCascade, double(p.sunFacing));
        else
            add("  shadow         lit fraction %.4g, no cascade (shadows off, sun down or beyond the maps; n.l %.4g)\n",
                double(p.shadowLit), double(p.sunFacing));
    }
    add("  depth          %.9g (%s), eye distance along the view axis %.6g\n", p.depth, p.depthCleared ? "cleared: nothing drawn" : "drawn",
        p.depthEyeDistance);
    add("  stencil        %d: %s\n", p.stencil, p.stencilMeaning.c_str());
    add("  radiance       %s (linear HDR)\n", vec(glm::dvec4(p.radiance)).c_str());
    if (p.reflectionResolution.empty())
        add("  reflection     %s (linear HDR; no mirrored scene drawn this frame)\n", vec(glm::dvec4(p.reflection)).c_str());
    else if (p.reflectionResolution == reflectionResolutionName(1))
        add("  reflection     %s (linear HDR; drawn at full resolution)\n", vec(glm::dvec4(p.reflection)).c_str());
    else
        add("  reflection     %s (linear HDR; drawn at %s resolution, %dx%d, upsampled bilinearly to this pixel)\n",
            vec(glm::dvec4(p.reflection)).c_str(), p.reflectionResolution.c_str(), p.reflectionWidth, p.reflectionHeight);
    add("  final          %d, %d, %d, %d (8-bit, displayed)\n", p.final.r, p.final.g, p.final.b, p.final.a);
    if (!p.waterScene.empty()) add("  water          the G-buffer and depth hold %s\n", p.waterScene.c_str());
    if (p.hasEncodingError) {
        if (std::isfinite(p.normalErrorDegrees))
            add("  encoding       against full (deferred): normal %.4g degrees, position %.4g units = %.3g depth steps\n",
                double(p.normalErrorDegrees), double(p.positionErrorUnits), double(p.positionErrorSteps));
        else
            text += "  encoding       against full (deferred): no common surface here (sky, or the flags differ)\n";
    }
    return text;
}

std::string probeJson(const PixelProbe& p) {
    struct JsonNumbers {
        JsonNumbers() { gJsonNumbers = true; }
        ~JsonNumbers() { gJsonNumbers = false; }
    } jsonNumbers;
    std::string json = "{\"x\": " + std::to_string(p.x) + ", \"y\": " + std::to_string(p.y) +
                       ", \"pipeline\": " + quoted(p.pipeline) + ", \"gbuffer\": " + quoted(p.layout) +
                       ", \"depth_convention\": " + quoted(p.depthConvention) + ", \"stored\": {";
    for (size_t i = 0; i < p.stored.size(); ++i)
        json += (i ? ", " : "") + quoted(p.stored[i].target) + ": {\"format\": " + quoted(p.stored[i].format) +
                ", \"stored_as\": " + quoted(p.stored[i].storedAs) + ", \"values\": [" +
                numbers(p.stored[i].values, "%.9g") + "]}";
    json += "}, \"sky\": " + std::string(p.sky ? "true" : "false");
    json += ", \"albedo\": {\"linear\": [" + vec(glm::dvec3(p.albedo)) + "], \"srgb\": [" + vec(glm::dvec3(p.albedoSrgb)) + "]}";
    json += ", \"normal\": {\"xyz\": [" + vec(glm::dvec3(p.normal)) + "], \"length\": " + numbers({p.normalLength}, "%.6g") + "}";
    // A sky pixel holds no surface: its world position is null (the stored texel is in "stored").
    json += ", \"position\": {\"camera_relative\": [" + vec(glm::dvec3(p.relativePosition)) + "], \"world\": " +
            (p.sky ? std::string("null") : "[" + vec(p.worldPosition, "%.9g") + "]") + ", \"eye_distance\": " + numbers({p.eyeDistance}, "%.6g") +
            (p.sceneDepth >= 0.0 ? ", \"from_depth_copy\": " + numbers({p.sceneDepth}, "%.9g") : "") + "}";
    json += ", \"info\": {\"specular_power\": " + numbers({p.specularPower}, "%g") + ", \"specular_intensity\": " +
            numbers({p.specularIntensity}, "%.6g") + ", \"flags\": " + std::to_string(p.flags) + ", \"flag_names\": [" +
            joined(p.flagNames, ", ", true) + "]}";
    json += ", \"depth\": {\"stored\": " + numbers({p.depth}, "%.9g") + ", \"eye_distance\": " +
            numbers({p.depthEyeDistance}, "%.6g") + ", \"cleared\": " + (p.depthCleared ? "true" : "false") + "}";
    json += ", \"stencil\": {\"value\": " + std::to_string(p.stencil) + ", \"meaning\": " + quoted(p.stencilMeaning) + "}";
    json += ", \"radiance\": [" + vec(glm::dvec4(p.radiance)) + "], \"reflection\": [" + vec(glm::dvec4(p.reflection)) + "]";
    json += ", \"reflection_resolution\": " +
            (p.reflectionResolution.empty() ? std::string("null")
                                            : "{\"name\": " + quoted(p.reflectionResolution) + ", \"width\": " +
                                                  std::to_string(p.reflectionWidth) + ", \"height\": " +
                                                  std::to_string(p.reflectionHeight) + "}");
    json += ", \"final\": [" + std::to_string(p.final.r) + ", " + std::to_string(p.final.g) + ", " +
            std::to_string(p.final.b) + ", " + std::to_string(p.final.a) + "]";
    json += ", \"lights_reaching\": " + std::to_string(p.lightsReaching) + ", \"lights_in_list\": " +
            std::to_string(p.lightsInList);
    json += ", \"shadow\": {\"lit_fraction\": " + numbers({p.shadowLit}, "%.6g") +
            ", \"cascade\": " + std::to_string(p.shadowCascade) + ", \"sun_facing\": " + numbers({p.sunFacing}, "%.6g") + "}";
    json += ", \"water_scene\": " + (p.waterScene.empty() ? std::string("null") : quoted(p.waterScene));
    json += ", \"encoding_error\": " +
            (p.hasEncodingError ? "{\"normal_degrees\": " + numbers({p.normalErrorDegrees}, "%.6g") +
                                      ", \"position_units\": " + numbers({p.positionErrorUnits}, "%.6g") +
                                      ", \"position_depth_steps\": " + numbers({p.positionErrorSteps}, "%.6g") + "}"
                                : std::string("null")) + "}";
    return json;
}

}  // namespace oasis
