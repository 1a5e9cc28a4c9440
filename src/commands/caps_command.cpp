// The capability report, as text or one JSON object, from a real session on a headless context
// (so "used" is what the renderer really took, including a compute path that failed to build).
#include "commands/caps_command.h"

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands/session.h"
#include "context/gl_context.h"
#include "io/json_text.h"

namespace oasis {
namespace {

std::vector<std::pair<std::string, std::string>> limitRows(const gl::Limits& l) {
    auto triple = [](const int v[3]) {
        return std::to_string(v[0]) + "," + std::to_string(v[1]) + "," + std::to_string(v[2]);
    };
    return {{"max_uniform_block_size", std::to_string(l.maxUniformBlockSize)},
            {"max_shader_storage_block_size", std::to_string(l.maxShaderStorageBlockSize)},
            {"max_shader_storage_buffer_bindings", std::to_string(l.maxShaderStorageBufferBindings)},
            {"max_vertex_shader_storage_blocks", std::to_string(l.maxVertexShaderStorageBlocks)},
            {"max_fragment_shader_storage_blocks", std::to_string(l.maxFragmentShaderStorageBlocks)},
            {"max_compute_shader_storage_blocks", std::to_string(l.maxComputeShaderStorageBlocks)},
            {"max_combined_shader_storage_blocks", std::to_string(l.maxCombinedShaderStorageBlocks)},
            {"max_draw_buffers", std::to_string(l.maxDrawBuffers)},
            {"max_color_attachments", std::to_string(l.maxColorAttachments)},
            {"max_texture_size", std::to_string(l.maxTextureSize)},
            {"max_samples", std::to_string(l.maxSamples)},
            {"max_compute_work_group_invocations", std::to_string(l.maxComputeWorkGroupInvocations)},
            {"max_compute_work_group_count", triple(l.maxComputeWorkGroupCount)},
            {"max_compute_work_group_size", triple(l.maxComputeWorkGroupSize)},
            {"max_compute_shared_memory_size", std::to_string(l.maxComputeSharedMemorySize)}};
}

void printText(const RenderSession& session) {
    const gl::Capabilities& caps = session.caps;
    // GL_VERSION names the API itself on ES ("OpenGL ES 3.2 Mesa ..."), not on desktop ("4.5 (Core ...").
    std::printf("oasis caps: %s%s\n", caps.es ? "" : "OpenGL ", caps.version.c_str());
    std::printf("  vendor    %s\n  renderer  %s\n  GLSL      %s\n  forced    %s\n  display   %s\n", caps.vendor.c_str(),
                caps.renderer.c_str(), caps.glslVersion.c_str(),
                caps.forced.any() ? caps.forced.list().c_str() : "nothing (--force LIST to switch features off)",
                headlessDisplayDescription().c_str());
    std::printf("limits (0: the context has no such query):\n");
    for (const auto& [name, value] : limitRows(caps.limits)) std::printf("  %-36s %s\n", name.c_str(), value.c_str());
    std::printf("extensions that matter (%s has some in core):\n", caps.apiVersionName().c_str());
    for (const auto& [name, present] : caps.relevantExtensions())
        std::printf("  %-36s %s\n", name.c_str(), present ? "yes" : "no");
    std::printf("features (available: the driver has it, --force aside; limited by: driver, forced tier or not "
                "asked for, - where used):\n");
    std::printf("  %-30s %-9s %-4s %-14s %s\n", "feature", "available", "used", "limited by", "reason");
    for (const gl::FeatureReport& feature : session.features()) {
        // The used column says "not used" already: the reason alone follows.
        const std::string notUsed = "not used: ";
        bool prefixed = feature.reason.compare(0, notUsed.size(), notUsed) == 0;
        std::printf("  %-30s %-9s %-4s %-14s %s\n", feature.name.c_str(), feature.available ? "yes" : "no",
                    feature.used ? "yes" : "no", feature.limitedBy.empty() ? "-" : feature.limitedBy.c_str(),
                    feature.reason.c_str() + (prefixed ? notUsed.size() : 0));
    }
    std::printf("driver workarounds (gl/driver_workarounds.h; --workarounds, --workarounds-file to change):\n");
    std::printf("  %-30s %-7s %s\n", "workaround", "applied", "why");
    for (const gl::WorkaroundState& state : session.workarounds.rows)
        std::printf("  %-30s %-7s %s\n", state.name.c_str(), state.applied ? "yes" : "no", state.why.c_str());
}

void printJson(const RenderSession& session) {
    const gl::Capabilities& caps = session.caps;
    std::string json = "{\"version\": " + jsonString(caps.version) + ", \"vendor\": " + jsonString(caps.vendor) +
                       ", \"renderer\": " + jsonString(caps.renderer) + ", \"glsl_version\": " +
                       jsonString(caps.glslVersion) + ", \"major\": " + std::to_string(caps.major) +
                       ", \"minor\": " + std::to_string(caps.minor) + ", \"forced\": " + jsonString(caps.forced.list()) +
                       ", \"api\": " + jsonString(caps.es ? "gles" : "gl") +
                       ", \"display\": " + jsonString(headlessDisplayDescription());
    json += ", \"limits\": {";
    bool first = true;
    for (const auto& [name, value] : limitRows(caps.limits)) {
        bool triple = value.find(',') != std::string::npos;
        json += (first ? "\"" : ", \"") + name + "\": " + (triple ? "[" + value + "]" : value);
        first = false;
    }
    json += "}, \"extensions\": {";
    first = true;
    for (const auto& [name, present] : caps.relevantExtensions()) {
        json += (first ? "\"" : ", \"") + name + "\": " + (present ? "true" : "false");
        first = false;
    }
    json += "}, \"features\": {";
    first = true;
    for (const gl::FeatureReport& feature : session.features()) {
        // "used" and "reason" first, as before: scripts match on them.
        json += (first ? "\"" : ", \"") + feature.name + "\": {\"used\": " + (feature.used ? "true" : "false") +
                ", \"reason\": " + jsonString(feature.reason) + ", \"available\": " +
                (feature.available ? "true" : "false") + ", \"limited_by\": " +
                (feature.limitedBy.empty() ? std::string("null") : jsonString(feature.limitedBy)) + "}";
        first = false;
    }
    json += "}, \"fallbacks\": [";
    first = true;
    for (const std::string& line : session.fallbacks()) {
        json += (first ? "" : ", ") + jsonString(line);
        first = false;
    }
    json += "], \"workarounds\": [";
    first = true;
    for (const gl::WorkaroundState& state : session.workarounds.rows) {
        json += std::string(first ? "" : ", ") + "{\"name\": " + jsonString(state.name) +
                ", \"applied\": " + (state.applied ? "true" : "false") + ", \"why\": " + jsonString(state.why) + "}";
        first = false;
    }
    std::printf("%s]}\n", json.c_str());
}

}  // namespace

int runCapsCommand(const Options& options) {
    try {
        HeadlessContext context(maxGlVersionFor(options.scene));
        RenderSession session(options, RenderSession::Shaders::CapabilitiesOnly);  // caps compiles nothing it needs
        if (options.json) printJson(session);
        else printText(session);
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "oasis: %s\n", error.what());
        return 1;
    }
}

}  // namespace oasis
