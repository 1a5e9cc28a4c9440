// Light paths: names, the capability-driven choice, the UBO layout.
#include "render/light_paths.h"

#include <algorithm>

#include "common/shared_constants.glsl"
#include "render/light_data.h"

namespace oasis {

namespace {

// The one table of light paths: the CLI and panel name, and the #define that selects it in
// shaders/common/lights.glsl.
struct LightsPathEntry {
    LightsPath path;
    const char* name;
    const char* define;
};
constexpr LightsPathEntry kLightsPaths[] = {
    {LightsPath::Ssbo, "ssbo", "LIGHTS_SSBO"},
    {LightsPath::SsboCount, "ssbo-count", "LIGHTS_SSBO_COUNT"},
    {LightsPath::Ubo, "ubo", "LIGHTS_UBO"},
};

const LightsPathEntry& entryOf(LightsPath path) {
    for (const LightsPathEntry& entry : kLightsPaths)
        if (entry.path == path) return entry;
    return kLightsPaths[0];
}

}  // namespace

const char* lightsPathName(LightsPath path) { return entryOf(path).name; }

bool parseLightsPath(const std::string& text, LightsPath& out) {
    for (const LightsPathEntry& entry : kLightsPaths)
        if (text == entry.name) { out = entry.path; return true; }
    return false;
}

const char* lightsPathDefine(LightsPath path) { return entryOf(path).define; }

std::string lightsVariantSuffix(LightsPath path) { return std::string(".lights-") + lightsPathName(path); }

std::string lightsPathNames() {
    std::string names;
    for (const LightsPathEntry& entry : kLightsPaths) names += std::string(names.empty() ? "" : ", ") + entry.name;
    return names;
}

LightsPathChoice chooseLightsPath(bool ssboAvailable, std::optional<LightsPath> forced,
                                  const std::string& whyNoSsbo) {
    if (forced) {
        if (*forced != LightsPath::Ubo && !ssboAvailable)
            return {LightsPath::Ubo, std::string("ubo (") + lightsPathName(*forced) + " was asked for but: " +
                                         whyNoSsbo + ")"};
        return {*forced, std::string(lightsPathName(*forced)) + " (forced)"};
    }
    // On OpenGL ES the capability's own words ("SSBOs present (ES 3.1)") say where they come from.
    if (ssboAvailable && whyNoSsbo.find("(ES ") != std::string::npos) return {LightsPath::Ssbo, "ssbo (" + whyNoSsbo + ")"};
    if (ssboAvailable) return {LightsPath::Ssbo, "ssbo (GL 4.3 / ARB_shader_storage_buffer_object present)"};
    return {LightsPath::Ubo, "ubo (" + whyNoSsbo + ")"};
}

UboLightLayout uboLightLayout(int maxUniformBlockSize, int maxUniformBlocksPerStage, int wantedLights) {
    UboLightLayout layout;
    layout.capacity = std::max(8, (maxUniformBlockSize / int(sizeof(PointLight))) / 8 * 8);
    int needed = std::max(1, (wantedLights + layout.capacity - 1) / layout.capacity);
    // The frame block and the count block take two of the stage's blocks.
    layout.blocks = std::max(1, std::min({needed, maxUniformBlocksPerStage - 2, OASIS_LIGHTS_UBO_MAX_BLOCKS}));
    return layout;
}

}  // namespace oasis
