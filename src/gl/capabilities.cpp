// Capabilities: measured from the context, combined with --force; the reasons are the report's words.
#include "gl/capabilities.h"

#include <epoxy/gl.h>

#include <sstream>
#include <tuple>

#include "common/shared_constants.glsl"

namespace oasis::gl {
namespace {

struct FallbackName {
    const char* name;
    bool ForcedFallbacks::*flag;
};
const FallbackName kFallbackNames[] = {
    {"no-ssbo", &ForcedFallbacks::noSsbo},
    {"no-compute", &ForcedFallbacks::noCompute},
    {"no-stencil-texturing", &ForcedFallbacks::noStencilTexturing},
    {"no-dsa", &ForcedFallbacks::noDsa},
    {"no-clip-control", &ForcedFallbacks::noClipControl},
    {"gl33", &ForcedFallbacks::gl33},
    {"gles30", &ForcedFallbacks::gles30},
    {"no-depth-clamp", &ForcedFallbacks::noDepthClamp},
    {"no-read-only-depth", &ForcedFallbacks::noReadOnlyDepth},
};

// What an OpenGL ES 3.0 context keeps of its extensions under --force gles30: the float colour
// targets oasis needs (ES 3.0 devices list them as extensions too) and debug output, nothing that
// adds features the ES 3.0 tier is defined without (clip distances, clip control, ...).
const char* const kGles30Extensions[] = {"GL_EXT_color_buffer_float", "GL_EXT_color_buffer_half_float",
                                         "GL_KHR_debug", "GL_EXT_debug_label"};

// WebGL 2's clip distances (WEBGL_clip_cull_distance, GLSL directive GL_ANGLE_clip_cull_distance).
constexpr const char* kWebglClipDistances = "GL_WEBGL_clip_cull_distance";

// Sets `reason` (when asked for) and returns `result`.
bool answer(bool result, std::string* reason, const std::string& text) {
    if (reason) *reason = text;
    return result;
}

// Where a feature comes from on each API: the desktop core version and ARB extension, the ES core
// version (0.0: none) and ES extension.
struct FeatureSource {
    int major, minor;
    const char* extension;
    int esMajor, esMinor;
    const char* esExtension;
    // WebGL 2's own name where it differs (emscripten lists WebGL's extensions GL_ prefixed).
    const char* webglExtension = nullptr;
};
const FeatureSource kSsbo{4, 3, "GL_ARB_shader_storage_buffer_object", 3, 1, nullptr};
const FeatureSource kCompute{4, 3, "GL_ARB_compute_shader", 3, 1, nullptr};
const FeatureSource kStencilTexturing{4, 3, "GL_ARB_stencil_texturing", 3, 1, nullptr};
const FeatureSource kDsa{4, 5, "GL_ARB_direct_state_access", 0, 0, nullptr};
const FeatureSource kDebug{4, 3, "GL_KHR_debug", 3, 2, "GL_KHR_debug"};
const FeatureSource kClipControl{4, 5, "GL_ARB_clip_control", 0, 0, "GL_EXT_clip_control"};
const FeatureSource k420Pack{4, 2, "GL_ARB_shading_language_420pack", 3, 1, nullptr};
const FeatureSource kGpuShader5{4, 0, "GL_ARB_gpu_shader5", 3, 2, "GL_EXT_gpu_shader5"};
const FeatureSource kGpuShader5Oes{4, 0, "GL_ARB_gpu_shader5", 3, 2, "GL_OES_gpu_shader5"};  // ES 3.1's other spelling
const FeatureSource kFloatTargets{3, 0, nullptr, 3, 2, "GL_EXT_color_buffer_float"};
const FeatureSource kClipDistances{3, 0, nullptr, 0, 0, "GL_EXT_clip_cull_distance", kWebglClipDistances};
const FeatureSource kDepthClamp{3, 2, "GL_ARB_depth_clamp", 0, 0, "GL_EXT_depth_clamp"};
// GL 4.5's feedback-loop rule (from ARB_texture_barrier): reads are undefined only of texels the
// draws write. ES is not assumed to allow it.
const FeatureSource kReadOnlyDepth{4, 5, "GL_ARB_texture_barrier", 0, 0, nullptr};  // desktop only
// glReadPixels of GL_DEPTH_COMPONENT / GL_STENCIL_INDEX: desktop core; ES only by this extension
// (Mesa's and NVIDIA's have it; WebGL 2 and ANGLE do not).
const FeatureSource kDepthStencilRead{1, 0, nullptr, 0, 0, "GL_NV_read_depth_stencil"};

// A version and extension list to ask: the tier oasis goes by (major/minor/extensions) or the
// context's own (beforeTier, where a forced tier replaced them).
struct Offer {
    bool es;
    int major, minor;
    const std::set<std::string>& extensions;
    bool atLeast(int wantMajor, int wantMinor) const {
        return major > wantMajor || (major == wantMajor && minor >= wantMinor);
    }
    bool has(const char* name) const { return extensions.count(name) != 0; }
};
Offer tierOffer(const Capabilities& caps) { return {caps.es, caps.major, caps.minor, caps.extensions}; }
Offer driverOffer(const Capabilities& caps) {
    if (!caps.beforeTier) return tierOffer(caps);
    return {caps.es, caps.beforeTier->major, caps.beforeTier->minor, caps.beforeTier->extensions};
}

// "GL 4.3" / "ES 3.1" when the core version has it, else the extension's name when listed, else "".
std::string source(const Offer& offer, const FeatureSource& feature) {
    int major = offer.es ? feature.esMajor : feature.major, minor = offer.es ? feature.esMinor : feature.minor;
    const char* extension = offer.es ? feature.esExtension : feature.extension;
    if (major > 0 && offer.atLeast(major, minor))
        return (offer.es ? "ES " : "GL ") + std::to_string(major) + "." + std::to_string(minor);
    if (extension && offer.has(extension)) return extension;
    if (offer.es && feature.webglExtension && offer.has(feature.webglExtension)) return feature.webglExtension;
    return {};
}
std::string source(const Capabilities& caps, const FeatureSource& feature) { return source(tierOffer(caps), feature); }

// "no GL 4.3 / GL_ARB_compute_shader" or "no ES 3.1" in the context's own terms; where a forced
// tier hides what the driver has, the tier is named as the limit: "no GL_EXT_clip_control in the
// forced ES 3.0 tier (--force gles30; the driver has GL_EXT_clip_control)".
std::string missing(const Capabilities& caps, const FeatureSource& feature) {
    int major = caps.es ? feature.esMajor : feature.major, minor = caps.es ? feature.esMinor : feature.minor;
    const char* extension = caps.es ? feature.esExtension : feature.extension;
    std::string text = "no ";
    if (major > 0) text += std::string(caps.es ? "ES " : "GL ") + std::to_string(major) + "." + std::to_string(minor);
    if (extension) text += std::string(major > 0 ? " / " : "") + extension;
    if (major == 0 && !extension) text += "such feature in OpenGL ES";
    std::string driverHas = source(driverOffer(caps), feature);
    if (caps.beforeTier && !driverHas.empty()) {
        bool gles30 = caps.es && caps.forced.gles30;
        text += std::string(" in the forced ") + (gles30 ? "ES 3.0 tier (--force gles30" : "GL 3.3 tier (--force gl33") +
                "; the driver has " + driverHas + ")";
    }
    return text;
}

int getInt(GLenum name) {
    GLint value = 0;
    glGetIntegerv(name, &value);
    return value;
}

std::string glString(GLenum name) {
    const GLubyte* text = glGetString(name);
    return text ? reinterpret_cast<const char*>(text) : "";
}

}  // namespace

// The light list sits at OASIS_BINDING_LIGHTS and, on the ssbo-count path, its count at
// OASIS_BINDING_LIGHT_COUNT: both read by light_volume.vert; lighting.frag declares them beside the
// tile lists and (desktop GL) the water bounds, which fullscreen.vert in the same program reads too
// (a block counts once per stage in the combined limit).
const StorageNeed kLightListStorage{"the SSBO light list", OASIS_BINDING_LIGHT_COUNT + 1, 2, 4, 0, 5};
// lsystem_interpret.comp binds its 7 buffers at 0-6.
const StorageNeed kPlantInterpreterStorage{"the compute plant interpretation", 7, 0, 0, 7, 7};

std::string storageShortfall(const Limits& limits, const StorageNeed& need) {
    const std::tuple<const char*, int, int> checks[] = {
        {"GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS", limits.maxShaderStorageBufferBindings, need.bindings},
        {"GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS", limits.maxVertexShaderStorageBlocks, need.vertexBlocks},
        {"GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS", limits.maxFragmentShaderStorageBlocks, need.fragmentBlocks},
        {"GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS", limits.maxComputeShaderStorageBlocks, need.computeBlocks},
        {"GL_MAX_COMBINED_SHADER_STORAGE_BLOCKS", limits.maxCombinedShaderStorageBlocks, need.combinedBlocks}};
    for (const auto& [name, have, needed] : checks)
        if (have < needed)
            return std::string(name) + " is " + std::to_string(have) + ", " + need.user + " needs " +
                   std::to_string(needed);
    return {};
}

std::string ForcedFallbacks::list() const {
    std::string text;
    for (const FallbackName& entry : kFallbackNames)
        if (this->*entry.flag) text += (text.empty() ? "" : ",") + std::string(entry.name);
    return text;
}

std::string ForcedFallbacks::forcedBy(const std::string& name) const {
    auto found = byWorkaround.find(name);
    return found != byWorkaround.end() ? "the driver workaround " + found->second : "--force " + name;
}

bool ForcedFallbacks::has(const std::string& name) const {
    return ("," + list() + ",").find("," + name + ",") != std::string::npos;
}

void ForcedFallbacks::forceByWorkaround(const std::string& name, const std::string& row) {
    if (has(name)) return;  // --force asked for it already
    std::string error;
    if (parseForcedFallbacks(name, *this, error)) byWorkaround[name] = row;  // the table's own names parse
}

const char* forcedFallbackNames() {
    return "no-ssbo, no-compute, no-stencil-texturing, no-dsa, no-clip-control, gl33, gles30, no-depth-clamp, "
           "no-read-only-depth";
}

const char* apiName(Api api) { return api == Api::Gles ? "gles" : "gl"; }

bool parseApi(const std::string& text, Api& api) {
    if (text == "gl") api = Api::Gl;
    else if (text == "gles") api = Api::Gles;
    else return false;
    return true;
}

std::string Capabilities::apiVersionName() const {
    return std::string(es ? "OpenGL ES " : "OpenGL ") + std::to_string(major) + "." + std::to_string(minor);
}

bool parseForcedFallbacks(const std::string& text, ForcedFallbacks& forced, std::string& error) {
    if (!text.empty() && text.back() == ',') { error = "empty name in '" + text + "'"; return false; }
    std::stringstream stream(text);
    std::string item;
    bool anyItem = false;
    while (std::getline(stream, item, ',')) {
        anyItem = true;
        bool known = false;
        for (const FallbackName& entry : kFallbackNames)
            if (item == entry.name) { forced.*entry.flag = true; known = true; }
        if (!known) {
            error = "unknown fallback '" + item + "' (one of: " + forcedFallbackNames() + ")";
            return false;
        }
    }
    if (!anyItem) { error = std::string("expects a list of: ") + forcedFallbackNames(); return false; }
    return true;
}

bool Capabilities::driverHasSsbo() const { return !source(driverOffer(*this), kSsbo).empty(); }
bool Capabilities::driverHasCompute() const { return !source(driverOffer(*this), kCompute).empty(); }
bool Capabilities::driverHasStencilTexturing() const { return !source(driverOffer(*this), kStencilTexturing).empty(); }
bool Capabilities::driverHasDsa() const { return !source(driverOffer(*this), kDsa).empty(); }
bool Capabilities::driverHasDebugOutput() const { return !source(driverOffer(*this), kDebug).empty(); }
bool Capabilities::driverHasClipControl() const { return !source(driverOffer(*this), kClipControl).empty(); }
bool Capabilities::driverHasClipDistances() const { return !source(driverOffer(*this), kClipDistances).empty(); }
bool Capabilities::driverHasDepthClamp() const { return !source(driverOffer(*this), kDepthClamp).empty(); }
bool Capabilities::driverHasNorm16Targets() const { return unforced().norm16TargetsAvailable(); }
bool Capabilities::driverHasFloatRenderTargets() const {
    Offer own = driverOffer(*this);
    if (es) return !source(own, kFloatTargets).empty();
    return own.atLeast(3, 0) || (own.has("GL_ARB_texture_float") && own.has("GL_ARB_color_buffer_float"));
}

Capabilities Capabilities::unforced() const {
    Capabilities own = *this;
    own.forced = {};
    // A driver workaround's fallback stays: the driver's bug is the driver's limit, not a tier's.
    for (const auto& [name, row] : forced.byWorkaround) own.forced.forceByWorkaround(name, row);
    if (beforeTier) {
        own.major = beforeTier->major;
        own.minor = beforeTier->minor;
        own.extensions = beforeTier->extensions;
        own.beforeTier.reset();
    }
    return own;
}

Availability Capabilities::availability(bool (Capabilities::*available)(std::string*) const) const {
    Availability answer;
    answer.tier = (this->*available)(&answer.reason);
    answer.driver = (unforced().*available)(nullptr);
    return answer;
}

std::string limitedBy(bool used, const Availability& availability) {
    if (used) return {};
    if (!availability.driver) return kLimitedByDriver;
    if (!availability.tier) return kLimitedByForcedTier;
    return kLimitedByNotAskedFor;
}

bool Capabilities::ssboAvailable(std::string* reason) const {
    if (forced.noSsbo) return answer(false, reason, "switched off by " + forced.forcedBy("no-ssbo"));
    std::string from = source(*this, kSsbo);
    if (from.empty()) return answer(false, reason, missing(*this, kSsbo));
    // ES 3.1 has SSBOs but may allow none in fragment shaders, where the light list is read.
    std::string shortfall = storageShortfall(limits, kLightListStorage);
    if (!shortfall.empty()) return answer(false, reason, "SSBOs present (" + from + ") but " + shortfall);
    return answer(true, reason, "SSBOs present (" + from + ")");
}

bool Capabilities::computeAvailable(std::string* reason) const {
    if (forced.noCompute) return answer(false, reason, "switched off by " + forced.forcedBy("no-compute"));
    std::string from = source(*this, kCompute);
    if (from.empty()) return answer(false, reason, missing(*this, kCompute));
    std::string ssboReason;
    if (!ssboAvailable(&ssboReason)) return answer(false, reason, "compute needs SSBOs: " + ssboReason);
    // Below GLSL 4.30 the interpreter's layout(binding) and `precise` need these as well (the
    // shader library enables the one found: render/shader_library.cpp, computeExtensionLines).
    std::string precise = source(*this, kGpuShader5);
    if (precise.empty()) precise = source(*this, kGpuShader5Oes);
    const std::pair<std::string, std::string> needs[] = {
        {source(*this, k420Pack), es ? "ES 3.1 layout(binding)" : "GL_ARB_shading_language_420pack"},
        {precise, es ? "ES 3.2 / GL_EXT_gpu_shader5 / GL_OES_gpu_shader5 (precise)" : "GL_ARB_gpu_shader5"}};
    for (const auto& [found, name] : needs)
        if (found.empty()) return answer(false, reason, "compute shaders present but no " + name + " for its GLSL");
    std::string shortfall = storageShortfall(limits, kPlantInterpreterStorage);
    if (!shortfall.empty()) return answer(false, reason, "compute shaders present (" + from + ") but " + shortfall);
    // `precise` by an extension (ES 3.1, desktop below 4.0) is said: the tiers differ by it.
    bool preciseCore = precise.rfind("GL ", 0) == 0 || precise.rfind("ES ", 0) == 0;
    return answer(true, reason, "compute shaders and SSBOs present (" + from + ")" +
                                    (preciseCore ? "" : ", precise by " + precise));
}

bool Capabilities::stencilTexturingAvailable(std::string* reason) const {
    if (forced.noStencilTexturing) return answer(false, reason, "switched off by " + forced.forcedBy("no-stencil-texturing"));
    std::string from = source(*this, kStencilTexturing);
    if (from.empty()) return answer(false, reason, missing(*this, kStencilTexturing));
    return answer(true, reason, "stencil texturing present (" + from + ")");
}

bool Capabilities::dsaAvailable(std::string* reason) const {
    if (forced.noDsa) return answer(false, reason, "switched off by " + forced.forcedBy("no-dsa"));
    std::string from = source(*this, kDsa);
    if (from.empty()) return answer(false, reason, missing(*this, kDsa));
    return answer(true, reason, "direct state access present (" + from + ")");
}

bool Capabilities::debugOutputAvailable(std::string* reason) const {
    std::string from = source(*this, kDebug);
    if (from.empty()) return answer(false, reason, missing(*this, kDebug));
    return answer(true, reason, "debug output and groups present (" + from + ")");
}

bool Capabilities::floatRenderTargetsAvailable(std::string* reason) const {
    if (es) {
        std::string from = source(*this, kFloatTargets);
        if (from.empty()) return answer(false, reason, missing(*this, kFloatTargets));
        return answer(true, reason, "RGBA16F/RGBA32F colour-renderable (" + from + ")");
    }
    if (!atLeast(3, 0) && !(hasExtension("GL_ARB_texture_float") && hasExtension("GL_ARB_color_buffer_float")))
        return answer(false, reason, "no GL 3.0 / GL_ARB_texture_float");
    return answer(true, reason, atLeast(3, 0) ? "RGBA16F/RGBA32F colour-renderable (core since GL 3.0)"
                                              : "GL_ARB_texture_float + GL_ARB_color_buffer_float");
}

bool Capabilities::clipControlAvailable(std::string* reason) const {
    if (forced.noClipControl) return answer(false, reason, "switched off by " + forced.forcedBy("no-clip-control"));
    std::string from = source(*this, kClipControl);
    if (from.empty()) return answer(false, reason, missing(*this, kClipControl));
    return answer(true, reason, "clip control present (" + from + ")");
}

bool Capabilities::clipDistancesAvailable(std::string* reason) const {
    std::string from = source(*this, kClipDistances);
    if (from.empty())
        return answer(false, reason, "fallback: the reflection's water-plane clip by discard (" + missing(*this, kClipDistances) + ")");
    return answer(true, reason, "gl_ClipDistance present (" + from + ")");
}

std::string Capabilities::clipDistanceDirective() const {
    return source(*this, kClipDistances) == kWebglClipDistances ? "GL_ANGLE_clip_cull_distance" : "GL_EXT_clip_cull_distance";
}

bool Capabilities::depthClampAvailable(std::string* reason) const {
    std::string from = source(*this, kDepthClamp);
    const char* fallback = "fallback: each shadow cascade's depth reaches towards the sun to the highest caster (one "
                           "past that flattened onto its front); the water mask and composite are drawn from a "
                           "full-screen triangle that finds the water plane per fragment (its depth written, clamped); "
                           "the light volumes are drawn unclamped (";
    if (forced.noDepthClamp) return answer(false, reason, fallback + std::string("switched off by ") + forced.forcedBy("no-depth-clamp") + ")");
    if (from.empty()) return answer(false, reason, fallback + missing(*this, kDepthClamp) + ")");
    return answer(true, reason, "GL_DEPTH_CLAMP present (" + from + ")");
}

bool Capabilities::depthStencilReadAvailable(std::string* reason) const {
    std::string from = source(*this, kDepthStencilRead);
    if (from.empty())
        return answer(false, reason, "fallback: depth and stencil drawn into colour targets and read from there (the "
                                     "probe, the pixel history, the stencil view's read-back; " +
                                     missing(*this, kDepthStencilRead) + ")");
    return answer(true, reason, "glReadPixels reads depth and stencil (" + from + ")");
}

bool Capabilities::norm16TargetsAvailable(std::string* reason) const {
    if (!es) {
        if (!atLeast(3, 0)) return answer(false, reason, "no GL 3.0");
        return answer(true, reason, "16-bit unorm colour-renderable (core since GL 3.0)");
    }
    // The driver's own list (beforeTier): a forced tier does not change which targets it can draw.
    // In a browser emscripten lists WebGL's names with and without the GL_ prefix.
    const std::set<std::string>& own = beforeTier ? beforeTier->extensions : extensions;
    for (const char* name : {"GL_EXT_texture_norm16", "EXT_texture_norm16"})
        if (own.count(name))
            return answer(true, reason, std::string("16-bit unorm colour-renderable (") + name +
                                            (extensions.count(name) ? "" : ", the driver's own: a forced tier does not hide it from the driver") +
                                            ")");
    return answer(false, reason, "no GL_EXT_texture_norm16 on this OpenGL ES driver");
}

bool Capabilities::readOnlyDepthAvailable(std::string* reason) const {
    const char* fallback = "fallback: the compact lighting that samples depth in place shades every pixel, the sky "
                           "drawn over its sky pixels (";
    if (forced.noReadOnlyDepth) return answer(false, reason, fallback + std::string("switched off by ") + forced.forcedBy("no-read-only-depth") + ")");
    if (es) return answer(false, reason, fallback + std::string("not relied on under OpenGL ES)"));
    std::string from = source(*this, kReadOnlyDepth);
    if (from.empty()) return answer(false, reason, fallback + missing(*this, kReadOnlyDepth) + ")");
    return answer(true, reason, "feedback-loop rule of " + from + ": reading a texture the draw only tests against is defined");
}

std::vector<std::pair<std::string, bool>> Capabilities::relevantExtensions() const {
    static const char* kNames[] = {
        "GL_ARB_shader_storage_buffer_object", "GL_ARB_compute_shader", "GL_ARB_stencil_texturing",
        "GL_ARB_direct_state_access", "GL_KHR_debug", "GL_ARB_shading_language_420pack", "GL_ARB_gpu_shader5",
        "GL_ARB_texture_float", "GL_ARB_color_buffer_float", "GL_ARB_uniform_buffer_object",
        "GL_ARB_explicit_attrib_location", "GL_ARB_explicit_uniform_location", "GL_ARB_texture_storage",
        "GL_ARB_timer_query", "GL_ARB_clip_control", "GL_ARB_texture_barrier"};
    static const char* kEsNames[] = {"GL_EXT_color_buffer_float", "GL_EXT_clip_cull_distance", "GL_EXT_clip_control",
                                     "GL_EXT_depth_clamp", "GL_KHR_debug", "GL_EXT_gpu_shader5", "GL_OES_gpu_shader5",
                                     "GL_EXT_disjoint_timer_query", "GL_NV_read_depth_stencil", "GL_EXT_texture_norm16"};
    std::vector<std::pair<std::string, bool>> list;
    if (es) {
        for (const char* name : kEsNames) list.emplace_back(name, hasExtension(name));
        return list;
    }
    for (const char* name : kNames) list.emplace_back(name, hasExtension(name));
    return list;
}

void applyForcedTier(Capabilities& caps) {
    ContextOwn own{caps.major, caps.minor, caps.extensions};
    bool changed = false;
    if (caps.forced.gles30 && caps.es && caps.atLeast(3, 1)) {  // Mesa gives ES 3.2 for any 3.x request
        caps.version += " (treated as ES 3.0: --force gles30)";
        caps.glslVersion += " (shaders as 300 es: --force gles30)";
        caps.major = 3;
        caps.minor = 0;
        changed = true;
    }
    if (caps.forced.gl33 && !caps.es && caps.atLeast(3, 4)) {  // a driver that gave more than the 3.3 asked for
        caps.version += " (treated as 3.3: --force gl33)";
        caps.major = 3;
        caps.minor = 3;
        changed = true;
    }
    if (caps.forced.gles30 && caps.es) {
        std::set<std::string> kept;
        for (const char* name : kGles30Extensions)
            if (caps.hasExtension(name)) kept.insert(name);
        changed = changed || kept != caps.extensions;
        caps.extensions = std::move(kept);
    }
    if (changed) caps.beforeTier = std::move(own);
}

Capabilities measureCapabilities(const ForcedFallbacks& forced) {
    Capabilities caps;
    caps.forced = forced;
    caps.version = glString(GL_VERSION);
    caps.vendor = glString(GL_VENDOR);
    caps.renderer = glString(GL_RENDERER);
    caps.glslVersion = glString(GL_SHADING_LANGUAGE_VERSION);
    caps.major = getInt(GL_MAJOR_VERSION);
    caps.minor = getInt(GL_MINOR_VERSION);
    caps.es = !epoxy_is_desktop_gl();
    int count = getInt(GL_NUM_EXTENSIONS);
    for (int i = 0; i < count; ++i)
        if (const GLubyte* name = glGetStringi(GL_EXTENSIONS, GLuint(i)))
            caps.extensions.insert(reinterpret_cast<const char*>(name));
    applyForcedTier(caps);
    Limits& limits = caps.limits;
    limits.maxUniformBlockSize = getInt(GL_MAX_UNIFORM_BLOCK_SIZE);
    limits.maxDrawBuffers = getInt(GL_MAX_DRAW_BUFFERS);
    limits.maxColorAttachments = getInt(GL_MAX_COLOR_ATTACHMENTS);
    limits.maxTextureSize = getInt(GL_MAX_TEXTURE_SIZE);
    limits.maxSamples = getInt(GL_MAX_SAMPLES);
    // The driver's limits, even where --force switches a feature off: the report shows both.
    const std::pair<int Limits::*, GLenum> storageLimits[] = {
        {&Limits::maxShaderStorageBlockSize, GL_MAX_SHADER_STORAGE_BLOCK_SIZE},
        {&Limits::maxShaderStorageBufferBindings, GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS},
        {&Limits::maxVertexShaderStorageBlocks, GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS},
        {&Limits::maxFragmentShaderStorageBlocks, GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS},
        {&Limits::maxComputeShaderStorageBlocks, GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS},
        {&Limits::maxCombinedShaderStorageBlocks, GL_MAX_COMBINED_SHADER_STORAGE_BLOCKS}};
    if (caps.driverHasSsbo())
        for (const auto& [field, name] : storageLimits) limits.*field = getInt(name);
    if (caps.driverHasCompute()) {
        limits.maxComputeWorkGroupInvocations = getInt(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS);
        limits.maxComputeSharedMemorySize = getInt(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE);
        for (GLuint axis = 0; axis < 3; ++axis) {
            glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, axis, &limits.maxComputeWorkGroupCount[axis]);
            glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_SIZE, axis, &limits.maxComputeWorkGroupSize[axis]);
        }
    }
    return caps;
}

}  // namespace oasis::gl
