// Sun path and sky colours over the day.
#include "scene/sky.h"

#include <algorithm>
#include <cmath>

namespace oasis {

double hourAtTime(double timeSeconds) {
    double hour = std::fmod(kStartHour + 24.0 * timeSeconds / kDayLengthSeconds, 24.0);
    if (hour < 0.0) hour += 24.0;  // a tiny negative remainder can round up to exactly 24
    return hour >= 24.0 ? 0.0 : hour;
}

SkyState skyAtHour(double hour) {
    const double tilt = glm::radians(35.0);
    double angle = (hour - 6.0) / 12.0 * M_PI;  // 0 at sunrise, pi at sunset
    glm::dvec3 sun(std::cos(angle), std::sin(angle) * std::cos(tilt), std::sin(angle) * std::sin(tilt));
    SkyState sky;
    sky.sunDirection = glm::vec3(glm::normalize(sun));
    float elevation = sky.sunDirection.y;
    // Daylight fades in over the first few degrees above the horizon and the light reddens there.
    float day = glm::smoothstep(-0.10f, 0.25f, elevation);
    float sunUp = glm::smoothstep(-0.01f, 0.08f, elevation);
    glm::vec3 lowSun(1.0f, 0.55f, 0.30f), highSun(1.0f, 0.96f, 0.88f);
    sky.sunRadiance = 2.4f * sunUp * glm::mix(lowSun, highSun, glm::smoothstep(0.0f, 0.4f, elevation));
    glm::vec3 nightZenith(0.004f, 0.008f, 0.025f), dayZenith(0.16f, 0.36f, 0.80f);
    glm::vec3 nightHorizon(0.015f, 0.02f, 0.04f), dayHorizon(0.62f, 0.74f, 0.88f);
    glm::vec3 duskHorizon(0.95f, 0.50f, 0.28f);
    float dusk = std::exp(-std::pow(elevation / 0.12f, 2.0f));  // strongest with the sun at the horizon
    sky.skyZenith = glm::mix(nightZenith, dayZenith, day);
    sky.skyHorizon = glm::mix(glm::mix(nightHorizon, dayHorizon, day), duskHorizon, 0.7f * dusk);
    sky.groundAmbient = glm::mix(glm::vec3(0.01f), glm::vec3(0.16f, 0.13f, 0.09f), day);
    return sky;
}

}  // namespace oasis
