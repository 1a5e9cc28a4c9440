// Time of day: where the sun is and what colour the sky and the light are at a given hour.
// The sky's look per pixel is shaders/common/sky.glsl; these are its per-frame inputs.
#pragma once
#include <glm/glm.hpp>

namespace oasis {

// Simulated hours per animation second; the default clock starts at 10:00.
constexpr double kDayLengthSeconds = 720.0;
constexpr double kStartHour = 10.0;
double hourAtTime(double timeSeconds);

struct SkyState {
    glm::vec3 sunDirection;   // unit, towards the sun
    glm::vec3 sunRadiance;    // zero below the horizon
    glm::vec3 skyZenith;
    glm::vec3 skyHorizon;
    glm::vec3 groundAmbient;
};

// Sun rises in the east (+X) at 6:00, sets in the west at 18:00, its path tilted to the south (+Z).
SkyState skyAtHour(double hour);

}  // namespace oasis
