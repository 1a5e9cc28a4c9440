// How the deferred pipeline adds the point lights: stencil volumes (two draws per light, the
// reference and the fallback) or tiled culling (a compute pass lists the lights of each screen
// tile, the lighting pass adds them). GL-free: the caller passes what the context offers, so the
// capability report and the unit tests use the same choice. The forward pipeline loops over every
// light in its fragments whatever the method.
#pragma once
#include <optional>
#include <string>

#include "render/light_paths.h"

namespace oasis {

enum class LightMethod { Volumes, Tiled };

// Without --light-method: the volumes. Measured at the default frame (docs/lights.md), tiled is
// faster from a few lights on, but volumes stay the reference every driver runs.
inline constexpr LightMethod kDefaultLightMethod = LightMethod::Volumes;

const char* lightMethodName(LightMethod method);  // "volumes", "tiled"
bool parseLightMethod(const std::string& text, LightMethod& out);
std::string lightMethodNames();                   // "volumes, tiled"

struct LightMethodChoice {
    LightMethod method = LightMethod::Volumes;
    std::string reason;  // "tiled (forced; compute shaders and SSBOs present (GL 4.3))"
};
// Tiled needs compute shaders and SSBOs (`computeAvailable`, `computeReason` the capability
// report's words either way); asked for without them it falls back to volumes and says why. It
// also falls back where the lights take the UBO path (`lightsPath`, forced or chosen): its tile
// lists live in a storage buffer, and the UBO path exists for drivers whose storage buffers break,
// so tiled there would put back exactly what the user took away.
LightMethodChoice chooseLightMethod(bool computeAvailable, std::optional<LightMethod> forced,
                                    const std::string& computeReason, LightsPath lightsPath);

}  // namespace oasis
