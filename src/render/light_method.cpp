// Light methods: the one table of names, and the capability-driven choice.
#include "render/light_method.h"

namespace oasis {
namespace {

struct LightMethodEntry {
    LightMethod method;
    const char* name;
};
constexpr LightMethodEntry kLightMethods[] = {
    {LightMethod::Volumes, "volumes"},
    {LightMethod::Tiled, "tiled"},
};

}  // namespace

const char* lightMethodName(LightMethod method) {
    for (const LightMethodEntry& entry : kLightMethods)
        if (entry.method == method) return entry.name;
    return kLightMethods[0].name;
}

bool parseLightMethod(const std::string& text, LightMethod& out) {
    for (const LightMethodEntry& entry : kLightMethods)
        if (text == entry.name) { out = entry.method; return true; }
    return false;
}

std::string lightMethodNames() {
    std::string names;
    for (const LightMethodEntry& entry : kLightMethods) names += std::string(names.empty() ? "" : ", ") + entry.name;
    return names;
}

LightMethodChoice chooseLightMethod(bool computeAvailable, std::optional<LightMethod> forced,
                                    const std::string& computeReason, LightsPath lightsPath) {
    LightMethod wanted = forced.value_or(kDefaultLightMethod);
    std::string how = forced ? "forced" : "default";
    if (wanted == LightMethod::Tiled && !computeAvailable)
        return {LightMethod::Volumes, "volumes (tiled was asked for but " + computeReason + ")"};
    if (wanted == LightMethod::Tiled && lightsPath == LightsPath::Ubo)
        return {LightMethod::Volumes,
                "volumes (tiled was asked for, but its tile lists are a storage buffer and the lights take the ubo path)"};
    if (wanted == LightMethod::Tiled) return {LightMethod::Tiled, "tiled (" + how + "; " + computeReason + ")"};
    return {LightMethod::Volumes, "volumes (" + how + ")"};
}

}  // namespace oasis
