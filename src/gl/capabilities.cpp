// Capabilities: measured from the context, combined with --force; the reasons are the report's words.
#include "gl/capabilities.h"

#include <epoxy/gl.h>

#include <sstream>

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
};

// Sets `reason` (when asked for) and returns `result`.
bool answer(bool result, std::string* reason, const std::string& text) {
    if (reason) *reason = text;
    return result;
}

// "GL 4.3" when the core version has it, else the extension's name when listed, else "".
std::string source(const Capabilities& caps, int major, int minor, const char* extension) {
    if (caps.atLeast(major, minor)) return "GL " + std::to_string(major) + "." + std::to_string(minor);
    if (extension && caps.hasExtension(extension)) return extension;
    return {};
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

std::string ForcedFallbacks::list() const {
    std::string text;
    for (const FallbackName& entry : kFallbackNames)
        if (this->*entry.flag) text += (text.empty() ? "" : ",") + std::string(entry.name);
    return text;
}

const char* forcedFallbackNames() { return "no-ssbo, no-compute, no-stencil-texturing, no-dsa, no-clip-control, gl33"; }

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

bool Capabilities::driverHasSsbo() const { return !source(*this, 4, 3, "GL_ARB_shader_storage_buffer_object").empty(); }
bool Capabilities::driverHasCompute() const { return !source(*this, 4, 3, "GL_ARB_compute_shader").empty(); }
bool Capabilities::driverHasStencilTexturing() const { return !source(*this, 4, 3, "GL_ARB_stencil_texturing").empty(); }
bool Capabilities::driverHasDsa() const { return !source(*this, 4, 5, "GL_ARB_direct_state_access").empty(); }
bool Capabilities::driverHasDebugOutput() const { return !source(*this, 4, 3, "GL_KHR_debug").empty(); }
bool Capabilities::driverHasClipControl() const { return !source(*this, 4, 5, "GL_ARB_clip_control").empty(); }
bool Capabilities::driverHasFloatRenderTargets() const {
    return atLeast(3, 0) || (hasExtension("GL_ARB_texture_float") && hasExtension("GL_ARB_color_buffer_float"));
}

bool Capabilities::ssboAvailable(std::string* reason) const {
    if (forced.noSsbo) return answer(false, reason, "switched off by --force no-ssbo");
    std::string from = source(*this, 4, 3, "GL_ARB_shader_storage_buffer_object");
    if (from.empty()) return answer(false, reason, "no GL 4.3 / GL_ARB_shader_storage_buffer_object");
    return answer(true, reason, "SSBOs present (" + from + ")");
}

bool Capabilities::computeAvailable(std::string* reason) const {
    if (forced.noCompute) return answer(false, reason, "switched off by --force no-compute");
    std::string from = source(*this, 4, 3, "GL_ARB_compute_shader");
    if (from.empty()) return answer(false, reason, "no GL 4.3 / GL_ARB_compute_shader");
    std::string ssboReason;
    if (!ssboAvailable(&ssboReason)) return answer(false, reason, "compute needs SSBOs: " + ssboReason);
    // Below GLSL 4.30 the interpreter's layout(binding) and `precise` need these as well.
    const std::pair<std::string, std::string> needs[] = {
        {source(*this, 4, 2, "GL_ARB_shading_language_420pack"), "GL_ARB_shading_language_420pack"},
        {source(*this, 4, 0, "GL_ARB_gpu_shader5"), "GL_ARB_gpu_shader5"}};
    for (const auto& [found, name] : needs)
        if (found.empty()) return answer(false, reason, "compute shaders present but no " + name + " for its GLSL");
    return answer(true, reason, "compute shaders and SSBOs present (" + from + ")");
}

bool Capabilities::stencilTexturingAvailable(std::string* reason) const {
    if (forced.noStencilTexturing) return answer(false, reason, "switched off by --force no-stencil-texturing");
    std::string from = source(*this, 4, 3, "GL_ARB_stencil_texturing");
    if (from.empty()) return answer(false, reason, "no GL 4.3 / GL_ARB_stencil_texturing");
    return answer(true, reason, "stencil texturing present (" + from + ")");
}

bool Capabilities::dsaAvailable(std::string* reason) const {
    if (forced.noDsa) return answer(false, reason, "switched off by --force no-dsa");
    std::string from = source(*this, 4, 5, "GL_ARB_direct_state_access");
    if (from.empty()) return answer(false, reason, "no GL 4.5 / GL_ARB_direct_state_access");
    return answer(true, reason, "direct state access present (" + from + ")");
}

bool Capabilities::debugOutputAvailable(std::string* reason) const {
    std::string from = source(*this, 4, 3, "GL_KHR_debug");
    if (from.empty()) return answer(false, reason, "no GL 4.3 / GL_KHR_debug");
    return answer(true, reason, "debug output and groups present (" + from + ")");
}

bool Capabilities::floatRenderTargetsAvailable(std::string* reason) const {
    if (!driverHasFloatRenderTargets()) return answer(false, reason, "no GL 3.0 / GL_ARB_texture_float");
    return answer(true, reason, atLeast(3, 0) ? "RGBA16F/RGBA32F colour-renderable (core since GL 3.0)"
                                              : "GL_ARB_texture_float + GL_ARB_color_buffer_float");
}

bool Capabilities::clipControlAvailable(std::string* reason) const {
    if (forced.noClipControl) return answer(false, reason, "switched off by --force no-clip-control");
    std::string from = source(*this, 4, 5, "GL_ARB_clip_control");
    if (from.empty()) return answer(false, reason, "no GL 4.5 / GL_ARB_clip_control");
    return answer(true, reason, "clip control present (" + from + ")");
}

std::vector<std::pair<std::string, bool>> Capabilities::relevantExtensions() const {
    static const char* kNames[] = {
        "GL_ARB_shader_storage_buffer_object", "GL_ARB_compute_shader", "GL_ARB_stencil_texturing",
        "GL_ARB_direct_state_access", "GL_KHR_debug", "GL_ARB_shading_language_420pack", "GL_ARB_gpu_shader5",
        "GL_ARB_texture_float", "GL_ARB_color_buffer_float", "GL_ARB_uniform_buffer_object",
        "GL_ARB_explicit_attrib_location", "GL_ARB_explicit_uniform_location", "GL_ARB_texture_storage",
        "GL_ARB_timer_query", "GL_ARB_clip_control"};
    std::vector<std::pair<std::string, bool>> list;
    for (const char* name : kNames) list.emplace_back(name, hasExtension(name));
    return list;
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
    if (forced.gl33 && caps.atLeast(3, 4)) {  // a driver that gave more than the 3.3 asked for
        caps.version += " (treated as 3.3: --force gl33)";
        caps.major = 3;
        caps.minor = 3;
    }
    int count = getInt(GL_NUM_EXTENSIONS);
    for (int i = 0; i < count; ++i)
        if (const GLubyte* name = glGetStringi(GL_EXTENSIONS, GLuint(i)))
            caps.extensions.insert(reinterpret_cast<const char*>(name));
    Limits& limits = caps.limits;
    limits.maxUniformBlockSize = getInt(GL_MAX_UNIFORM_BLOCK_SIZE);
    limits.maxDrawBuffers = getInt(GL_MAX_DRAW_BUFFERS);
    limits.maxColorAttachments = getInt(GL_MAX_COLOR_ATTACHMENTS);
    limits.maxTextureSize = getInt(GL_MAX_TEXTURE_SIZE);
    limits.maxSamples = getInt(GL_MAX_SAMPLES);
    // The driver's limits, even where --force switches a feature off: the report shows both.
    if (caps.driverHasSsbo()) limits.maxShaderStorageBlockSize = getInt(GL_MAX_SHADER_STORAGE_BLOCK_SIZE);
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
