// The shading oracle (check/shading_oracle.h): a seeded sample of pixels, each either left out
// by kind or shaded on the CPU and compared with the driver's Radiance; a failure named by the first
// term that differs from what the shading probe records there.
#include "check/shading_oracle.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <set>
#include <stdexcept>

#include "check/oracle_inputs.h"
#include "common/shared_constants.glsl"
#include "frame/pixel_probe.h"
#include "frame/renderer.h"
#include "frame/shading_probe.h"

namespace oasis {
namespace {

// Half floats keep 10 mantissa bits: a store rounds (or, as llvmpipe, truncates) a value by less
// than 2^-10 of itself. The driver's float arithmetic before it (pow with exponents up to 255,
// exp, normalize) adds under 2^-14 (measured: docs/check.md), so 2^-10 plus an eighth of it.
constexpr double kBoundPerStore = 1.125 / 1024.0;
// Below half's smallest normal (2^-14) its steps are absolute (2^-24): relative to that floor.
constexpr double kHalfNormalFloor = 1.0 / 16384.0;
// A cosine this near 0 may fall either side of the shader's `> 0` tests in float: its specular
// term jumps there, so the CPU cannot say which side the driver took.
constexpr double kGrazingCosine = 1e-5;
constexpr uint32_t kSampleSeed = 40006;  // issue 40, item 6

const char* const kSky = "sky";
const char* const kWater = "water (its surface and reflection are not rebuilt)";
const char* const kReflected = "reflected surface";
const char* const kSunGrazing = "sun grazing (N.L within 1e-5 of 0)";
const char* const kLightGrazing = "point light grazing (N.L within 1e-5 of 0)";
const char* const kIllConditioned = "position from depth ill-conditioned";
// What the radiance may move, relative, within its inputs' float uncertainty and still be checked:
// the bound's slack over the half-float store.
constexpr double kConditionSlack = kBoundPerStore - 1.0 / 1024.0;

struct GlPixel {
    int x = 0, y = 0;  // GL's window coordinates, bottom row 0
};

// `count` distinct pixels of `from`, the same for every driver and run (a 32-bit LCG, not the
// standard library's distributions, which differ between libraries); none already `taken`.
std::vector<GlPixel> seededChoice(const std::vector<GlPixel>& from, int count, uint32_t seed,
                                  std::set<std::pair<int, int>>& taken) {
    std::vector<GlPixel> chosen;
    std::set<size_t> tried;
    uint32_t state = seed;
    while (int(chosen.size()) < count && tried.size() < from.size()) {
        state = state * 1664525u + 1013904223u;
        size_t k = size_t((uint64_t(state) * uint64_t(from.size())) >> 32);
        if (!tried.insert(k).second || !taken.insert({from[k].x, from[k].y}).second) continue;
        chosen.push_back(from[k]);
    }
    return chosen;
}

// Pixels a pixel in from the frame's edges; with `pointLit`, only those whose surface (not water)
// lies inside some point light's sphere as the CPU reads the inputs.
std::vector<GlPixel> interiorPixels(const OracleInputs& in, bool pointLit) {
    std::vector<GlPixel> pixels;
    for (int y = 1; y + 1 < in.height; ++y)
        for (int x = 1; x + 1 < in.width; ++x) {
            OracleSurface s;
            if (pointLit && (oracleWaterAt(in, x, y) || !oracleSurfaceAt(in, x, y, s))) continue;
            if (pointLit && std::none_of(in.lights.begin(), in.lights.end(), [&](const PointLight& light) {
                    return glm::distance(glm::dvec3(light.positionRadius), oracleLitPosition(in.frame, s)) <
                           double(light.positionRadius.w);
                }))
                continue;
            pixels.push_back({x, y});
        }
    return pixels;
}

// The sample: three quarters over the whole interior, a quarter among the pixels the point lights
// reach (a few percent of a frame: a uniform sample alone could miss them all).
std::vector<GlPixel> samplePixels(const OracleInputs& in, int count) {
    std::set<std::pair<int, int>> taken;
    std::vector<GlPixel> sample = seededChoice(interiorPixels(in, false), count - count / 4, kSampleSeed, taken);
    std::vector<GlPixel> lit = seededChoice(interiorPixels(in, true), count - int(sample.size()), kSampleSeed + 1, taken);
    sample.insert(sample.end(), lit.begin(), lit.end());
    return sample;
}

void countLeftOut(ShadingOracle& result, const std::string& kind) {
    for (auto& [name, count] : result.leftOut)
        if (name == kind) {
            ++count;
            return;
        }
    result.leftOut.push_back({kind, 1});
}

// Whether some light reaching the surface meets it edge-on (pointLightRadiance's `diffuse <= 0`).
bool lightGrazes(const OracleInputs& in, const OracleSurface& s) {
    glm::dvec3 position = oracleLitPosition(in.frame, s), n = glm::normalize(s.normal);
    for (const PointLight& light : in.lights) {
        glm::dvec3 toLight = glm::dvec3(light.positionRadius) - position;
        double distance = glm::length(toLight);
        if (distance < light.positionRadius.w && std::fabs(glm::dot(n, toLight / std::max(distance, 1e-4))) < kGrazingCosine)
            return true;
    }
    return false;
}

// One pixel: why it is left out, or "" with its shading and the stores its radiance went through.
std::string shadePixel(const OracleInputs& in, GlPixel p, PixelShading& shading, int& stores) {
    if (oracleWaterAt(in, p.x, p.y)) return kWater;
    OracleSurface s;
    if (!oracleSurfaceAt(in, p.x, p.y, s)) return kSky;
    if (s.flags & OASIS_SURFACE_REFLECTED) return kReflected;
    glm::dvec3 n = glm::normalize(s.normal);
    double nDotL = glm::dot(n, glm::dvec3(in.frame.sunDirection));
    if (std::fabs(nDotL) < kGrazingCosine) return kSunGrazing;
    if (lightGrazes(in, s)) return kLightGrazing;
    OracleSunShadow sun;
    // Facing away from the sun, its visibility multiplies nothing: any value gives the same radiance.
    if (nDotL > 0.0 && in.frame.shadow.x != 0.0f) {
        if (!in.shadowMapsUnreadable.empty()) return "shadowed, shadow maps unreadable";
        sun = oracleSunShadow(in.frame, in.shadowMaps, oracleLitPosition(in.frame, s), n);
        if (!sun.leftOut.empty()) return sun.leftOut;
    }
    shading = oracleShadePixel(in.frame, s, sun.lit, sun.cascade, in.lights);
    stores = 1 + (in.lightVolumes ? int(shading.lights.size()) : 0);
    // A position the driver rebuilt from depth is only known to its float error: where the shading
    // moves beyond the slack within it (a point light's window near its radius, far away), the CPU
    // cannot say what the driver's own rounding made of it.
    if (double error = oracleRebuiltPositionError(in, p.x, p.y); error > 0.0) {
        for (double scale : {1.0 - error, 1.0 + error}) {
            OracleSurface moved = s;
            moved.relativePosition *= scale;
            glm::dvec3 other = oracleShadePixel(in.frame, moved, sun.lit, sun.cascade, in.lights).radiance;
            glm::dvec3 change = glm::abs(other - shading.radiance) / glm::max(glm::abs(shading.radiance), glm::dvec3(kHalfNormalFloor));
            if (std::max({change.x, change.y, change.z}) > kConditionSlack) return kIllConditioned;
        }
    }
    return {};
}

// The largest channel's |driver - CPU| relative to the CPU's value (or half's normal floor).
double relativeError(const glm::dvec3& cpu, const float* driver) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        double d = driver[c];
        if (!std::isfinite(d)) return INFINITY;
        worst = std::max(worst, std::fabs(d - cpu[c]) / std::max(std::fabs(cpu[c]), kHalfNormalFloor));
    }
    return worst;
}

// A recorded term against the CPU's, component by component, each relative to itself or, for a
// component small beside the term's largest, to 2^-8 of that (a unit vector's near-zero parts).
double termError(const std::vector<double>& cpu, const std::vector<double>& recorded) {
    double largest = kHalfNormalFloor;
    for (size_t c = 0; c < cpu.size() && c < recorded.size(); ++c)
        largest = std::max({largest, std::fabs(cpu[c]), std::fabs(recorded[c])});
    double worst = 0.0;
    for (size_t c = 0; c < cpu.size() && c < recorded.size(); ++c) {
        if (!std::isfinite(recorded[c])) return INFINITY;
        double scale = std::max({std::fabs(cpu[c]), std::fabs(recorded[c]), largest / 256.0});
        worst = std::max(worst, std::fabs(cpu[c] - recorded[c]) / scale);
    }
    return worst;
}

std::string values(const std::vector<double>& v) {
    std::string text;
    for (double x : v) {
        char number[32];
        std::snprintf(number, sizeof number, "%s%.6g", text.empty() ? "" : ", ", x);
        text += number;
    }
    return "(" + text + ")";
}

// The first of the CPU's terms (in the probe's order, each light before their sum) that differs
// from what the frame's GLSL records at the pixel; "radiance" where every term agrees (what differs
// is then Radiance's stores themselves). The probe's terms only name: the CPU never reads them.
std::string nameDifferingTerm(Renderer& renderer, const OracleInputs& in, GlPixel p, const PixelShading& cpu,
                              std::string& detail) {
    PixelProbe probe;
    probe.x = p.x;
    probe.y = in.height - 1 - p.y;
    probe.stencil = in.stencil[size_t(p.y) * size_t(in.width) + size_t(p.x)];
    std::vector<ShadedSurface> recorded;
    try {
        recorded = probeShading(renderer, probe);
    } catch (const std::exception& error) {
        detail += "; the terms could not be recorded to name one (" + std::string(error.what()) + ")";
        return "radiance";
    }
    std::vector<NamedTerm> terms = oracleNamedTerms(cpu);
    std::stable_partition(terms.begin(), terms.end(), [](const NamedTerm& t) { return t.name.rfind("light ", 0) == 0; });
    for (const NamedTerm& term : terms) {
        const ShadingTerm* frame = recorded.empty() ? nullptr : recorded.front().find(term.name);
        if (!frame || termError(term.values, frame->values) <= shadingOracleBound()) continue;
        detail += "; " + term.name + ": the frame's GLSL " + values(frame->values) + ", the CPU " + values(term.values);
        return term.name;
    }
    detail += "; every recorded term agrees with the CPU's: Radiance's stores differ";
    return "radiance";
}

}  // namespace

double shadingOracleBound() { return kBoundPerStore; }

ShadingOracle runShadingOracle(Renderer& renderer, int samples) {
    return runShadingOracle(renderer, readOracleInputs(renderer), samples);
}

ShadingOracle runShadingOracle(Renderer& renderer, const OracleInputs& in, int samples) {
    ShadingOracle result;
    result.ran = true;
    result.bound = kBoundPerStore;
    result.inputs = in.source;
    GlPixel worst;
    PixelShading worstShading;
    for (GlPixel p : samplePixels(in, samples)) {
        ++result.pixelsSampled;
        PixelShading shading;
        int stores = 1;
        if (std::string why = shadePixel(in, p, shading, stores); !why.empty()) {
            countLeftOut(result, why);
            continue;
        }
        ++result.pixelsChecked;
        const float* driver = &in.radiance[(size_t(p.y) * size_t(in.width) + size_t(p.x)) * 4];
        double error = relativeError(shading.radiance, driver) / stores;
        if (!(error <= result.maxRelativeError)) {
            result.maxRelativeError = error;
            worst = p;
            worstShading = shading;
        }
    }
    result.verdict = result.maxRelativeError <= result.bound ? "pass" : "fail";
    if (result.verdict == "fail") {
        const float* driver = &in.radiance[(size_t(worst.y) * size_t(in.width) + size_t(worst.x)) * 4];
        char text[240];
        std::snprintf(text, sizeof text, "at pixel %d,%d (top-left 0,0): Radiance (%.6g, %.6g, %.6g), the CPU (%.6g, %.6g, %.6g)",
                      worst.x, in.height - 1 - worst.y, driver[0], driver[1], driver[2], worstShading.radiance.x,
                      worstShading.radiance.y, worstShading.radiance.z);
        result.detail = text;
        result.differingTerm = nameDifferingTerm(renderer, in, worst, worstShading, result.detail);
    }
    return result;
}

}  // namespace oasis
