// Where this frame's water can be seen, from the terrain grid's vertices (the argument is in
// visible_water.h). Heights are computed on first use and kept while the grid stays put.
#include "scene/visible_water.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace oasis {
namespace {

constexpr double kPi = 3.14159265358979323846;
// How far the GPU's vertices may sit from where this file puts them: its sin, cos and pow are
// allowed a few ulps more than the CPU's (1e-4 radians is a hundred times what GPUs document).
constexpr double kAzimuthSlack = 1e-4;
constexpr double kRadiusSlack = 1e-4;

double wrapToPi(double angle) {
    angle = std::fmod(angle + kPi, 2.0 * kPi);
    return (angle < 0.0 ? angle + 2.0 * kPi : angle) - kPi;
}

// terrain.vert's convention: a point at azimuth a lies at radius * (sin a, -cos a).
double azimuthOf(double x, double z) { return std::atan2(x, -z); }

bool sameShape(const TerrainShape& a, const TerrainShape& b) {
    return a.frequency == b.frequency && a.amplitude == b.amplitude && a.baseHeight == b.baseHeight &&
           a.octaves == b.octaves;
}

}  // namespace

bool TerrainGridPlacement::operator==(const TerrainGridPlacement& other) const {
    return sameShape(shape, other.shape) && sameGridDensity(density, other.density) &&
           wedge.centralAzimuth == other.wedge.centralAzimuth && wedge.halfWidth == other.wedge.halfWidth &&
           wedge.ringRatio == other.wedge.ringRatio && viewDistance == other.viewDistance &&
           cameraXZ == other.cameraXZ;
}

float VisibleWaterBound::dryMargin(float radius, float nearPlane) {
    const float depthStep = radius * radius / (std::max(nearPlane, 1e-6f) * 16777216.0f);
    return 0.1f + 4.0f * depthStep;
}

void VisibleWaterBound::prepare(const TerrainShape& shape, const TerrainGridDensity& density, const TerrainWedge& wedge,
                                float viewDistance, const CameraView& view, float waterLevel) {
    TerrainGridPlacement key{shape, density, wedge, viewDistance, {view.pose.position.x, view.pose.position.z}};
    if (!keyValid_ || !(key == key_)) {
        key_ = key;
        keyValid_ = true;
        origins_ = terrainNoiseOrigins(shape, key.cameraXZ);
        size_t vertices = density.rings >= 0 && density.segments >= 0
                              ? size_t(density.rings + 1) * size_t(density.segments + 1) : 0;
        heights_.assign(vertices, std::numeric_limits<float>::quiet_NaN());
        size_t cells = density.rings >= 1 && density.segments >= 1 ? size_t(density.rings) * size_t(density.segments) : 0;
        cellLowest_.assign(cells, std::numeric_limits<float>::quiet_NaN());
        heightsComputed_ = 0;
    }
    camera_ = view.pose.position;
    waterLevel_ = waterLevel;
    nearPlane_ = view.projection.nearPlane;
    active_ = false;
    bool finite = std::isfinite(camera_.x) && std::isfinite(camera_.y) && std::isfinite(camera_.z) &&
                  std::isfinite(wedge.halfWidth) && std::isfinite(wedge.ringRatio);
    if (!finite || density.rings < 1 || density.segments < 1 || !(wedge.ringRatio > 1.0f) ||
        !(wedge.halfWidth > 0.0f) || !(camera_.y > double(waterLevel) + 1e-3))
        return;
    // The near plane clips nothing nearer the eye than `reach` (its corners are furthest); the
    // ground must stay below the eye by more than that within `reach` around it, so the ground a
    // ray crosses is never clipped away in front of the water it hides.
    double tanV = std::tan(double(view.projection.verticalFovDegrees) * kPi / 360.0);
    double reach = double(nearPlane_) * std::sqrt(1.0 + tanV * tanV * (1.0 + double(view.aspect) * view.aspect));
    double cosHalfSegment = std::cos(double(wedge.halfWidth) / double(density.segments));
    float highest = -std::numeric_limits<float>::infinity();
    for (int ring = 0; ring <= density.rings; ++ring) {
        for (int segment = 0; segment <= density.segments; ++segment)
            highest = std::max(highest, vertexHeight(ring, segment));
        if (double(ringRadius(ring)) * cosHalfSegment > reach) break;  // the cells inside this ring cover the reach
    }
    active_ = camera_.y - reach > double(highest) + double(dryMargin(0.0f, nearPlane_));
}

float VisibleWaterBound::ringRadius(int ring) const {
    if (ring == 0) return 0.0f;
    return key_.density.firstRingRadius * std::pow(key_.wedge.ringRatio, float(ring - 1));
}

float VisibleWaterBound::vertexHeight(int ring, int segment) {
    float& height = heights_[size_t(ring) * size_t(key_.density.segments + 1) + size_t(segment)];
    if (std::isnan(height)) {
        // terrain.vert's arithmetic: the segment's fraction, the azimuth across the wedge.
        float fraction = float(segment) / float(key_.density.segments);
        float azimuth = key_.wedge.centralAzimuth + (2.0f * fraction - 1.0f) * key_.wedge.halfWidth;
        glm::vec2 offset = ringRadius(ring) * glm::vec2(std::sin(azimuth), -std::cos(azimuth));
        height = terrainHeightFromCamera(key_.shape, origins_, offset).x;
        ++heightsComputed_;
    }
    return height;
}

float VisibleWaterBound::cellLowest(int ring, int segment) {
    float& lowest = cellLowest_[size_t(ring) * size_t(key_.density.segments) + size_t(segment)];
    if (std::isnan(lowest)) {
        // The cell's two triangles interpolate these four heights: its lowest point is one of them.
        lowest = std::min(std::min(vertexHeight(ring, segment), vertexHeight(ring, segment + 1)),
                          std::min(vertexHeight(ring + 1, segment), vertexHeight(ring + 1, segment + 1)));
    }
    return lowest;
}

bool VisibleWaterBound::anyCellWet(int firstRing, int lastRing, int firstSegment, int lastSegment) {
    for (int ring = firstRing; ring <= lastRing; ++ring) {
        float dryAbove = waterLevel_ + dryMargin(ringRadius(ring + 1), nearPlane_);
        for (int segment = firstSegment; segment <= lastSegment; ++segment)
            if (!(cellLowest(ring, segment) > dryAbove)) return true;
    }
    return false;
}

bool VisibleWaterBound::mirrorImageMayShow(const glm::dvec3& low, const glm::dvec3& high) {
    if (!active_) return true;
    // Only what is above the water is mirrored (the mirrored passes clip the rest).
    const double level = double(waterLevel_);
    const double lowY = std::max(low.y, level);
    if (!(high.y > lowY)) return true;
    // A mirrored point P' = (x, 2 level - y, z) is seen where the ray from the eye to it crosses
    // the plane: horizontally, the fraction t = eye's height / (eye's height + y's) of the way from
    // the eye to (x, z). Around the box's footprint, a disc (centre c, radius rho): the crossings
    // lie in the polar sector of azimuths c's +- asin(rho / |c|) and radii t (|c| -+ rho).
    const double eyeAbove = camera_.y - level;
    const double nearestT = eyeAbove / (eyeAbove + (high.y - level));
    const double furthestT = eyeAbove / (eyeAbove + (lowY - level));
    const double centreX = 0.5 * (low.x + high.x) - camera_.x, centreZ = 0.5 * (low.z + high.z) - camera_.z;
    const double rho = 0.5 * std::hypot(high.x - low.x, high.z - low.z);
    const double centreDistance = std::hypot(centreX, centreZ);
    const double nearest = std::max(0.0, centreDistance - rho) * nearestT;
    const double furthest = (centreDistance + rho) * furthestT;
    if (!std::isfinite(nearest) || !std::isfinite(furthest)) return true;

    const TerrainGridDensity& density = key_.density;
    const TerrainWedge& wedge = key_.wedge;
    const double segmentAngle = 2.0 * double(wedge.halfWidth) / double(density.segments);
    const double cosHalfSegment = std::cos(0.5 * segmentAngle);
    // Beyond the last ring's chords no ground is drawn; the water quad reaches further.
    if (furthest >= 0.999 * double(ringRadius(density.rings)) * cosHalfSegment) return true;

    const bool fullCircle = wedge.halfWidth >= float(kPi);
    int firstSegment = 0, lastSegment = density.segments - 1;
    if (centreDistance > rho) {
        double fromCentral = wrapToPi(azimuthOf(centreX, centreZ) - double(wedge.centralAzimuth));
        double spread = std::asin(rho / centreDistance) + kAzimuthSlack;  // and the GPU's rounding
        double lowest = fromCentral - spread, highest = fromCentral + spread;
        bool insideWedge = lowest >= -double(wedge.halfWidth) && highest <= double(wedge.halfWidth);
        // Outside the wedge no ground is drawn (and nothing is on screen); keep the box.
        if (!insideWedge && !fullCircle) return true;
        if (insideWedge) {
            firstSegment = std::max(0, int(std::floor((lowest + wedge.halfWidth) / segmentAngle)));
            lastSegment = std::min(density.segments - 1, int(std::floor((highest + wedge.halfWidth) / segmentAngle)));
        }
    } else if (!fullCircle) {
        return true;  // the crossings surround the eye: part of them lies outside the wedge
    }
    // Ring i >= 1 lies at first * ratio^(i - 1); cell i spans radii [r_i cos(half segment), r_{i+1}],
    // so it meets [nearest, furthest] when r_{i+1} >= nearest and r_i cos(half segment) <= furthest.
    // The radii are widened by kRadiusSlack for the GPU's rounding of pow.
    auto ringIndex = [&](double radius) {
        double first = double(density.firstRingRadius);
        return radius <= first ? radius / first : 1.0 + std::log(radius / first) / std::log(double(wedge.ringRatio));
    };
    int firstRing = std::max(0, int(std::floor(ringIndex(nearest * (1.0 - kRadiusSlack)))) - 1);
    int lastRing = std::min(density.rings - 1,
                            int(std::floor(ringIndex(furthest * (1.0 + kRadiusSlack) / cosHalfSegment))));
    return anyCellWet(firstRing, lastRing, firstSegment, lastSegment);
}

}  // namespace oasis
