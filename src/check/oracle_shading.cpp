// The CPU twin of shadeSurface and the point lights (check/oracle_shading.h): the GLSL line by
// line, in double, so that what the driver's float arithmetic and half-float storage add is the
// only difference left.
#include "check/oracle_shading.h"

#include <algorithm>
#include <cmath>

#include "common/shared_constants.glsl"

namespace oasis {
namespace {

using glm::dvec3;

dvec3 rgb(const glm::vec4& v) { return dvec3(v.x, v.y, v.z); }

bool isReflected(const OracleSurface& s) { return (s.flags & OASIS_SURFACE_REFLECTED) != 0u; }

// The eye ray to the surface: a reflected surface is seen from the mirrored camera.
dvec3 eyeToSurfaceOf(const OracleSurface& s) {
    dvec3 p = s.relativePosition;
    return isReflected(s) ? dvec3(p.x, -p.y, p.z) : p;
}

// common/water.glsl
double underwaterLengthOf(const FrameData& frame, dvec3 eye, dvec3 point) {
    double level = frame.water.x;
    double eyeHeight = eye.y - level, pointHeight = point.y - level;
    if (eyeHeight >= 0.0 && pointHeight >= 0.0) return 0.0;
    double length = glm::distance(eye, point);
    if (eyeHeight < 0.0 && pointHeight < 0.0) return length;
    double crossing = eyeHeight / (eyeHeight - pointHeight);
    return eyeHeight < 0.0 ? length * crossing : length * (1.0 - crossing);
}

dvec3 waterScatterOf(const FrameData& frame) {
    dvec3 light = 0.5 * (rgb(frame.skyZenith) + rgb(frame.skyHorizon)) +
                  0.25 * rgb(frame.sunRadiance) * std::max(double(frame.sunDirection.y), 0.0);
    return rgb(frame.waterTint) * light;
}

dvec3 transmittanceOf(const FrameData& frame, double length) {
    return glm::exp(-double(frame.water.y) * length * dvec3(1.0, 0.45, 0.3));
}

// common/sky.glsl: the fog's colour, the sky without its disk, clouds and stars.
dvec3 skyGradientOf(const FrameData& frame, dvec3 direction) {
    double up = std::clamp(direction.y, 0.0, 1.0);
    dvec3 gradient = glm::mix(rgb(frame.skyHorizon), rgb(frame.skyZenith), std::pow(up, 0.5));
    double down = std::clamp(-direction.y, 0.0, 1.0);
    return gradient * (1.0 - 0.35 * std::sqrt(down));
}

dvec3 sunGlowOf(const FrameData& frame, dvec3 direction) {
    double towardsSun = std::max(glm::dot(direction, rgb(frame.sunDirection)), 0.0);
    return rgb(frame.sunRadiance) * (0.06 * std::pow(towardsSun, 6.0) + 0.25 * std::pow(towardsSun, 200.0));
}

dvec3 fogColourOf(const FrameData& frame, dvec3 direction) {
    return skyGradientOf(frame, dvec3(direction.x, std::max(direction.y, 0.0), direction.z)) + sunGlowOf(frame, direction);
}

double fogWeightOf(const FrameData& frame, double eyeDistance) {
    return smoothstepOf(frame.terrainGridCounts.z, frame.terrainGridCounts.w, eyeDistance);
}

void appendVector(std::vector<double>& values, dvec3 v) { values.insert(values.end(), {v.x, v.y, v.z}); }

NamedTerm vectorTerm(const char* name, dvec3 v) { return {name, {v.x, v.y, v.z}}; }

NamedTerm vectorTerm(const char* name, dvec3 v, double w) { return {name, {v.x, v.y, v.z, w}}; }

}  // namespace

glm::dvec3 oracleLitPosition(const FrameData& frame, const OracleSurface& s) {
    dvec3 p = s.relativePosition;
    if (isReflected(s)) p.y = 2.0 * (double(frame.water.x) - double(frame.cameraPosition.y)) - p.y;
    return p;
}

SurfaceTerms oracleShadeSurface(const FrameData& frame, const OracleSurface& s, double shadow, int cascade) {
    SurfaceTerms t;
    t.reflected = isReflected(s);
    dvec3 eyeToSurface = eyeToSurfaceOf(s);
    t.normal = glm::normalize(s.normal);
    t.toCamera = glm::normalize(-eyeToSurface);
    t.toSun = rgb(frame.sunDirection);
    t.sunRadiance = rgb(frame.sunRadiance);
    t.nDotL = glm::dot(t.normal, t.toSun);
    t.shadow = shadow;
    t.cascade = cascade;
    t.sunAtSurface = t.sunRadiance * shadow;
    t.diffuse = std::max(t.nDotL, 0.0);
    dvec3 halfway = glm::normalize(t.toSun + t.toCamera);
    t.normalisation = (s.specularPower + 8.0) / 25.13274;  // the GLSL's constant, not pi's digits
    t.nDotH = glm::dot(t.normal, halfway);
    t.specular = t.diffuse > 0.0
                     ? s.specularIntensity * t.normalisation * std::pow(std::max(t.nDotH, 0.0), s.specularPower)
                     : 0.0;
    dvec3 skyAmbient = glm::mix(rgb(frame.skyHorizon), rgb(frame.skyZenith), 0.5);
    t.ambient = glm::mix(rgb(frame.groundAmbient), skyAmbient, 0.5 + 0.5 * t.normal.y);
    t.albedo = s.albedo;
    t.specularPower = s.specularPower;
    t.diffusePart = s.albedo * t.sunAtSurface * t.diffuse;
    t.ambientPart = s.albedo * t.ambient;
    t.specularPart = t.sunAtSurface * t.specular;
    t.lit = t.ambientPart + t.diffusePart + t.specularPart;
    t.afterWater = t.lit;
    if (!t.reflected) {
        dvec3 eye = rgb(frame.cameraPosition);
        t.underLength = underwaterLengthOf(frame, eye, eye + s.relativePosition);
        t.waterCrossed = transmittanceOf(frame, t.underLength);
        t.waterScatter = waterScatterOf(frame);
        if (t.underLength > 0.0) t.afterWater = t.lit * t.waterCrossed + t.waterScatter * (1.0 - t.waterCrossed);
    }
    t.eyeDistance = glm::length(eyeToSurface);
    t.fog = fogWeightOf(frame, t.eyeDistance);
    t.fogColour = fogColourOf(frame, -t.toCamera);
    t.surface = glm::mix(t.afterWater, t.fogColour, t.fog);
    return t;
}

double oraclePointLightFalloff(double distanceToLight, double radius) {
    double ratio = distanceToLight / radius;
    double window = std::clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
    return window * window / (distanceToLight * distanceToLight + 1.0);
}

glm::dvec3 oraclePointLightRadiance(const FrameData& frame, const OracleSurface& s, const PointLight& light) {
    dvec3 position = oracleLitPosition(frame, s);
    dvec3 toLight = rgb(light.positionRadius) - position;
    double radius = light.positionRadius.w;
    double distanceToLight = glm::length(toLight);
    if (distanceToLight >= radius) return dvec3(0.0);
    dvec3 l = toLight / std::max(distanceToLight, 1e-4);
    dvec3 n = glm::normalize(s.normal);
    double diffuse = std::max(glm::dot(n, l), 0.0);
    if (diffuse <= 0.0) return dvec3(0.0);
    dvec3 halfway = glm::normalize(l - glm::normalize(eyeToSurfaceOf(s)));
    double normalisation = (s.specularPower + 8.0) / 25.13274;
    double specular = s.specularIntensity * normalisation * std::pow(std::max(glm::dot(n, halfway), 0.0), s.specularPower);
    dvec3 irradiance = rgb(light.colourIntensity) *
                       (double(light.colourIntensity.w) * oraclePointLightFalloff(distanceToLight, radius));
    return (s.albedo * diffuse + dvec3(specular)) * irradiance;
}

glm::dvec3 oraclePointLightTransfer(const FrameData& frame, const OracleSurface& s) {
    dvec3 transfer(1.0);
    if (!isReflected(s)) {
        dvec3 eye = rgb(frame.cameraPosition);
        double under = underwaterLengthOf(frame, eye, eye + s.relativePosition);
        if (under > 0.0) transfer = transmittanceOf(frame, under);
    }
    return transfer * (1.0 - fogWeightOf(frame, glm::length(eyeToSurfaceOf(s))));
}

PixelShading oracleShadePixel(const FrameData& frame, const OracleSurface& s, double shadow, int cascade,
                              const std::vector<PointLight>& lights) {
    PixelShading shading;
    shading.surface = oracleShadeSurface(frame, s, shadow, cascade);
    dvec3 transfer = oraclePointLightTransfer(frame, s);
    for (size_t i = 0; i < lights.size(); ++i) {
        dvec3 share = oraclePointLightRadiance(frame, s, lights[i]);
        if (share == dvec3(0.0)) continue;
        shading.lights.push_back({int(i), share * transfer});
        shading.lightsSum += share * transfer;
    }
    shading.radiance = shading.surface.surface + shading.lightsSum;
    return shading;
}

std::vector<NamedTerm> oracleNamedTerms(const PixelShading& shading) {
    const SurfaceTerms& t = shading.surface;
    std::vector<NamedTerm> terms = {
        vectorTerm("to_sun", t.toSun),
        vectorTerm("sun_radiance", t.sunRadiance),
        vectorTerm("to_camera", t.toCamera),
        vectorTerm("normal", t.normal, t.nDotL),
        {"shadow", {t.shadow, double(t.cascade)}},
        vectorTerm("sun_at_surface", t.sunAtSurface),
        {"specular_lobe", {t.diffuse, t.normalisation, t.nDotH, t.specular}},
        vectorTerm("ambient", t.ambient),
        vectorTerm("albedo", t.albedo, t.specularPower),
        vectorTerm("diffuse_part", t.diffusePart),
        vectorTerm("ambient_part", t.ambientPart),
        vectorTerm("specular_part", t.specularPart),
        vectorTerm("lit", t.lit),
        vectorTerm("water_crossed", t.waterCrossed, t.underLength),
    };
    if (!t.reflected) terms.push_back(vectorTerm("water_scatter", t.waterScatter));
    terms.push_back(vectorTerm("after_water", t.afterWater));
    terms.push_back({"fog", {t.fog, t.eyeDistance}});
    terms.push_back(vectorTerm("fog_colour", t.fogColour));
    terms.push_back(vectorTerm("surface", t.surface));
    terms.push_back(vectorTerm("lights", shading.lightsSum, double(shading.lights.size())));
    for (const LightShare& light : shading.lights) {
        NamedTerm term{"light " + std::to_string(light.index), {}};
        appendVector(term.values, light.radiance);
        terms.push_back(term);
    }
    terms.push_back(vectorTerm("radiance", shading.radiance));
    return terms;
}

}  // namespace oasis
