// The shadow quality table and the cascades' fit to the view (see shadow_cascades.h).
#include "render/shadow_cascades.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace oasis {
namespace {


// Where the slices split: this mix of the logarithmic split (even texel density per eye distance)
// and the uniform one, from kNearest (closer surfaces take cascade 0's texels anyway).
constexpr double kLogarithmicShare = 0.9;
constexpr double kNearest = 1.0;
// Shadows fade out over the last part of the distance, ending at it.
constexpr double kFadeShare = 0.15;
// A contained box's depth range is at most this many of its radii: the 32-bit float depth's step
// at the back of the range (2^-24 of it) then stays under a quarter of a 2048 map's texel. Only a
// sun under a degree above the horizon needs more; past it casters are flattened onto the front.
constexpr double kMostDepthRangeInRadii = 4096.0;

// Whether the origin lies in the triangle abc (either winding, edges included).
bool originInTriangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    auto side = [](glm::dvec2 p, glm::dvec2 q) { return p.x * q.y - p.y * q.x; };
    double ab = side(a, b), bc = side(b, c), ca = side(c, a);
    return (ab >= 0.0 && bc >= 0.0 && ca >= 0.0) || (ab <= 0.0 && bc <= 0.0 && ca <= 0.0);
}

double originToSegment(glm::dvec2 a, glm::dvec2 b) {
    glm::dvec2 d = b - a;
    double length2 = glm::dot(d, d);
    double t = length2 > 0.0 ? std::clamp(-glm::dot(a, d) / length2, 0.0, 1.0) : 0.0;
    return glm::length(a + d * t);
}

// The horizontal distances from the camera (the origin) of the box's square (light-space x, y
// within +-radius, depth from its back at -radius towards the sun) between camera-relative heights
// low and high. `toLight` maps camera-relative points to light space; its light z points to the
// sun. The swept box lies within the hull of its square's corners at the lowest and highest depth
// any corner needs, so the distances are those of the hull of 8 points: the farthest corner, and
// 0 or the nearest hull edge.
glm::vec2 casterReach(const glm::dmat4& toLight, double radius, double low, double high) {
    glm::dmat4 fromLight = glm::inverse(toLight);
    glm::dvec3 step = glm::dvec3(fromLight[2]);  // camera-relative change per unit of light depth
    double nearDepth = -radius, farDepth = -radius;
    bool first = true;
    for (int corner = 0; corner < 4; ++corner) {
        glm::dvec4 at = fromLight * glm::dvec4(corner & 1 ? radius : -radius, corner & 2 ? radius : -radius, 0.0, 1.0);
        if (step.y <= 1e-9) return {0.0f, 1e30f};  // the sun at the horizon: no bound along its rays
        double lowDepth = (low - at.y) / step.y, highDepth = (high - at.y) / step.y;
        nearDepth = first ? lowDepth : std::min(nearDepth, lowDepth);
        farDepth = first ? highDepth : std::max(farDepth, highDepth);
        first = false;
    }
    nearDepth = std::max(nearDepth, -radius);
    farDepth = std::max(farDepth, nearDepth);
    std::array<glm::dvec2, 8> points;
    double farthest = 0.0;
    for (int i = 0; i < 8; ++i) {
        glm::dvec4 p = fromLight * glm::dvec4(i & 1 ? radius : -radius, i & 2 ? radius : -radius,
                                              i & 4 ? farDepth : nearDepth, 1.0);
        points[size_t(i)] = glm::dvec2(p.x, p.z);
        farthest = std::max(farthest, glm::length(points[size_t(i)]));
    }
    double nearest = 1e30;
    for (size_t i = 0; i < 8; ++i)
        for (size_t j = i + 1; j < 8; ++j) {
            nearest = std::min(nearest, originToSegment(points[i], points[j]));
            for (size_t k = j + 1; k < 8; ++k)
                if (originInTriangle(points[i], points[j], points[k])) nearest = 0.0;
        }
    return {float(nearest), float(farthest)};
}

// The light depth (from the box's centre, towards the sun) up to which a caster no higher than
// `high` (camera-relative) can stand above the box's square: the highest of its four corners'.
double casterFrontDepth(const glm::dmat4& toLight, double radius, double high) {
    glm::dmat4 fromLight = glm::inverse(toLight);
    glm::dvec3 step = glm::dvec3(fromLight[2]);  // camera-relative change per unit of light depth
    if (step.y <= 1e-9) return 1e30;             // the sun at the horizon
    double front = -1e30;
    for (int corner = 0; corner < 4; ++corner) {
        glm::dvec4 at = fromLight * glm::dvec4(corner & 1 ? radius : -radius, corner & 2 ? radius : -radius, 0.0, 1.0);
        front = std::max(front, (high - at.y) / step.y);
    }
    return front;
}

}  // namespace

const std::vector<ShadowQuality>& shadowQualities() {
    // The one table of shadow qualities (a function's static: the bench's knob table, built at
    // start-up in another file, reads it). The bench times and compares every level.
    static const std::vector<ShadowQuality> qualities = {
        {"low", 2, 1024},
        {"medium", 4, 1024},
        {"high", 4, 2048},
    };
    return qualities;
}

const ShadowQuality* findShadowQuality(const std::string& name) {
    for (const ShadowQuality& quality : shadowQualities())
        if (name == quality.name) return &quality;
    return nullptr;
}

const ShadowQuality& defaultShadowQuality() { return *findShadowQuality(ShadowSettings{}.quality); }

std::string shadowQualityNames() {
    std::string names;
    for (const ShadowQuality& quality : shadowQualities()) names += (names.empty() ? "" : ", ") + std::string(quality.name);
    return names;
}

ShadowCascades fitShadowCascades(const CameraView& view, const glm::vec3& toSun, const ShadowQuality& quality,
                                 float distance, glm::vec2 casterHeights, ShadowCasterDepth casterDepth) {
    ShadowCascades cascades;
    cascades.count = std::clamp(quality.cascades, 1, OASIS_SHADOW_MAX_CASCADES);
    const double far = std::max(double(distance), 2.0 * kNearest);
    const double tanY = std::tan(glm::radians(double(view.projection.verticalFovDegrees)) * 0.5);
    const double tanX = tanY * double(view.aspect);
    const double k2 = tanX * tanX + tanY * tanY;  // a slice corner's squared offset per unit of depth
    const glm::dvec3 forward = glm::dvec3(view.pose.forward());
    const glm::dvec3 camera = view.pose.position;

    // The sun's rotation (world -> light view, the light looking along -toSun).
    glm::dvec3 sun = glm::normalize(glm::dvec3(toSun));
    glm::dvec3 up = std::fabs(sun.y) > 0.99 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    glm::dmat4 rotation = glm::lookAt(glm::dvec3(0.0), -sun, up);

    double start = kNearest;
    for (int c = 0; c < cascades.count; ++c) {
        double fraction = double(c + 1) / double(cascades.count);
        double end = c + 1 == cascades.count
                         ? far
                         : kLogarithmicShare * kNearest * std::pow(far / kNearest, fraction) +
                               (1.0 - kLogarithmicShare) * (kNearest + (far - kNearest) * fraction);
        // The smallest sphere around the slice [start, end] of depth centred on the axis.
        double centreDepth = std::min(end, 0.5 * (start + end) * (1.0 + k2));
        double radius = std::max(std::sqrt((end - centreDepth) * (end - centreDepth) + end * end * k2),
                                 std::sqrt((centreDepth - start) * (centreDepth - start) + start * start * k2));
        // Rounded up to a 1/64 step of its power of two, so float noise never changes the size.
        double step = std::exp2(std::ceil(std::log2(radius))) / 64.0;
        radius = std::ceil(radius / step) * step;
        double texel = 2.0 * radius / double(quality.mapSize);

        // The centre in light space, world coordinates in double, snapped to whole texels.
        glm::dvec3 centreWorld = camera + forward * centreDepth;
        glm::dvec3 centreLight = glm::dvec3(rotation * glm::dvec4(centreWorld, 1.0));
        centreLight.x = std::floor(centreLight.x / texel) * texel;
        centreLight.y = std::floor(centreLight.y / texel) * texel;
        // Camera-relative p -> light space about the snapped centre: R p + (R camera - centre).
        glm::dvec3 offset = glm::dvec3(rotation * glm::dvec4(camera, 1.0)) - centreLight;
        glm::mat4 lightView = glm::mat4(glm::mat3(rotation));
        lightView[3] = glm::vec4(glm::vec3(offset), 1.0f);
        glm::dmat4 toLight = glm::dmat4(glm::dmat3(rotation));
        toLight[3] = glm::dvec4(offset, 1.0);
        // Depth across the sphere; casters nearer the sun than its front are clamped onto it
        // (ShadowPass draws with depth clamping), so nothing between the sun and the slice is lost.
        // Contained: the front moves towards the sun to the highest caster (ShadowCasterDepth).
        double front = radius;
        if (casterDepth == ShadowCasterDepth::Contained)
            front = std::clamp(casterFrontDepth(toLight, radius, double(casterHeights.y) - camera.y), radius,
                               (kMostDepthRangeInRadii - 1.0) * radius);
        glm::mat4 projection = glm::ortho(float(-radius), float(radius), float(-radius), float(radius),
                                          float(-front), float(radius));
        cascades.matrices[size_t(c)] = projection * lightView;
        cascades.sliceEnd[c] = float(end);
        cascades.texel[c] = float(texel);
        cascades.depthRange[c] = float(front + radius);
        cascades.casterReach[size_t(c)] = casterReach(toLight, radius, double(casterHeights.x) - camera.y,
                                                      double(casterHeights.y) - camera.y);
        start = end;
    }
    cascades.fadeEnd = float(far);
    cascades.fadeStart = float(far * (1.0 - kFadeShare));
    return cascades;
}

}  // namespace oasis
