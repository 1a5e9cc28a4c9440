// Light paths: names, the capability-driven choice, the UBO layout.
#include "render/light_paths.h"

#include "common/shared_constants.glsl"


#include <algorithm>

#include "render/light_data.h"

namespace oasis {

const char* lightsPathName(LightsPath path) {
    switch (path) {
        case LightsPath::Ssbo: return "ssbo";
        case LightsPath::SsboCount: return "ssbo-count";
        case LightsPath::Ubo: return "ubo";
    }
    return "";
}

bool parseLightsPath(const std::string& text, LightsPath& out) {
    for (LightsPath path : {LightsPath::Ssbo, LightsPath::SsboCount, LightsPath::Ubo})
        if (text == lightsPathName(path)) { out = path; return true; }
    return false;
}

const char* lightsPathDefine(LightsPath path) {
    switch (path) {
        case LightsPath::Ssbo: return "LIGHTS_SSBO";
        case LightsPath::SsboCount: return "LIGHTS_SSBO_COUNT";
        case LightsPath::Ubo: return "LIGHTS_UBO";
    }
    return "";
}

std::string lightsVariantSuffix(LightsPath path) { return std::string(".lights-") + lightsPathName(path); }

std::string lightsPathNames() { return "ssbo, ssbo-count, ubo"; }

LightsPathChoice chooseLightsPath(bool ssboAvailable, std::optional<LightsPath> forced,
                                  const std::string& whyNoSsbo) {
    if (forced) {
        if (*forced != LightsPath::Ubo && !ssboAvailable)
            return {LightsPath::Ubo, std::string("ubo (") + lightsPathName(*forced) + " was asked for but: " +
                                         whyNoSsbo + ")"};
        return {*forced, std::string(lightsPathName(*forced)) + " (forced)"};
    }
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
