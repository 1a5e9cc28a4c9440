// Builds a frame's CPU-side state and its uniform block contents.
#include "render/frame_setup.h"

#include <algorithm>
#include <cmath>

#include "common/shared_constants.glsl"

namespace oasis {
namespace {

// The detail noise layers (shaders/common/detail_noise.glsl): noise units per world unit and
// drift in noise units per second.
struct DetailNoiseLayer {
    int index;
    double scale;
    glm::dvec2 drift;
};
const DetailNoiseLayer kDetailNoiseLayers[] = {
    {OASIS_DETAIL_RIPPLE_BROAD, 0.12, {0.05, 0.03}},
    {OASIS_DETAIL_RIPPLE_FINE, 0.55, {-0.11, 0.07}},
    {OASIS_DETAIL_GROUND_BROAD, 0.02, {0.0, 0.0}},
    {OASIS_DETAIL_GROUND_FINE, 0.25, {0.0, 0.0}},
    // Gusts drift with the wind (vegetation.vert's direction, 0.943 0.333) at 0.6 noise units a second.
    {OASIS_DETAIL_WIND_GUSTS, 0.012, {-0.943 * 0.6, -0.333 * 0.6}},
    // Clouds on a deck at OASIS_CLOUD_ALTITUDE (common/sky.glsl): cells of about 1,800 and 450
    // world units drifting with the wind at about 9 and 12 units a second.
    {OASIS_DETAIL_CLOUDS_BROAD, 1.0 / 1800.0, {-0.943 * 0.005, -0.333 * 0.005}},
    {OASIS_DETAIL_CLOUDS_FINE, 1.0 / 450.0, {-0.943 * 0.027, -0.333 * 0.027}},
    // Rock's vertical cracks (common/terrain.glsl): the noise's zero lines, cells of about 2.5 units.
    {OASIS_DETAIL_ROCK_CRACKS, 0.4, {0.0, 0.0}},
};
static_assert(std::size(kDetailNoiseLayers) == OASIS_DETAIL_LAYERS, "one table row per detail layer");

}  // namespace

const ReflectionResolution* findReflectionResolution(const std::string& name) {
    for (const ReflectionResolution& resolution : kReflectionResolutions)
        if (name == resolution.name) return &resolution;
    return nullptr;
}

const MirroredPlantCullMode* findMirroredPlantCull(const std::string& name) {
    for (const MirroredPlantCullMode& mode : kMirroredPlantCullModes)
        if (name == mode.name) return &mode;
    return nullptr;
}

const char* reflectionResolutionName(int divisor) {
    for (const ReflectionResolution& resolution : kReflectionResolutions)
        if (divisor == resolution.divisor) return resolution.name;
    return kReflectionResolutions[0].name;
}

FrameSetup prepareFrame(const SceneSettings& scene, int width, int height, const DepthConvention& depth,
                        ShadowCasterDepth casterDepth) {
    FrameConditions conditions;
    conditions.depth = depth;
    conditions.casterDepth = casterDepth;
    return prepareFrame(scene, width, height, conditions);
}

TerrainGridPlacement terrainGridPlacement(const SceneSettings& scene, const FrameSetup& frame) {
    const glm::dvec3& camera = frame.view.pose.position;
    return {scene.terrain, scene.grid, frame.wedge, scene.viewDistance, glm::dvec2(camera.x, camera.z)};
}

bool lightingSamplesDepthTarget(const FrameSetup& frame) {
    return frame.work.depthReadInPlace && frame.positionFromDepth;
}

namespace {

// The plants' atlas in the frame block, and whether the reflection's plants are culled on the CPU.
// At a reduced reflection resolution the reflection's stencil marks the whole plane and the
// upsample's taps reach past the water's edge, so images on land may show: no cull there. Auto:
// only when the grid (and so every height the bound computes) is the last frame's.
void preparePlants(FrameSetup& setup, const SceneSettings& scene, int height, const FrameConditions& conditions) {
    // The billboards pick their atlas mip level from their projected size (vegetation.vert).
    float pixelsPerUnit = float(height) / (2.0f * std::tan(glm::radians(setup.view.projection.verticalFovDegrees) * 0.5f));
    setup.data.vegetationAtlas = glm::vec4(float(conditions.atlasColumns), float(conditions.atlasRows),
                                           conditions.cellTexels, pixelsPerUnit);
    if (conditions.plantDrawnBounds) {  // trimmed billboards: each cell's drawn bounds
        const std::vector<glm::vec4>& drawn = *conditions.plantDrawnBounds;
        for (size_t cell = 0; cell < drawn.size() && cell < size_t(OASIS_PLANT_MAX_CELLS); ++cell)
            setup.data.plantDrawnBounds[cell] = drawn[cell];
    }
    if (!setup.vegetationEnabled || !conditions.plantAtlas) return;
    bool still = conditions.lastGrid && *conditions.lastGrid == terrainGridPlacement(scene, setup);
    MirroredPlantCull cull = scene.work.mirroredPlantCull;
    setup.mirroredPlantsCulled = setup.reflectionsActive && setup.reflectionDivisor == 1 &&
                                 (cull == MirroredPlantCull::On || (cull == MirroredPlantCull::Auto && still));
}

// What the context and the request decide: the layout's depth reading, the water's rectangle, the
// lights' path and method (the UBO path drops what it cannot hold), whether the tone map is fused.
void applyConditions(FrameSetup& setup, const SceneSettings& scene, const FrameConditions& conditions) {
    setup.positionFromDepth = conditions.positionFromDepth;
    setup.waterBounded = conditions.waterBoundsAvailable && scene.water.reflectionBounds;
    if (setup.waterBounded)  // the shaders' copy of it: the mirrored billboards cull by the rectangle
        setup.data.water.w = float(unsigned(setup.data.water.w) | OASIS_WATER_BOUNDED_FLAG);
    setup.lightsPath = conditions.lightsPath;
    setup.lightMethod = conditions.lightMethod;
    if (setup.lightsPath == LightsPath::Ubo && int(setup.lights.size()) > conditions.uboMaxLights) {
        setup.lightsDropped = int(setup.lights.size()) - conditions.uboMaxLights;
        setup.lights.resize(size_t(conditions.uboMaxLights));
    }
    // The separate tone map stays for a frame stopped early (its targets shown as they were) and
    // when the deferred light volumes add to Radiance after LightingPass (it cannot write Final).
    bool volumesAfterLighting = conditions.deferred && setup.lightMethod == LightMethod::Volumes && !setup.lights.empty();
    setup.toneMapFused = scene.work.fuseToneMap && conditions.runsToEnd && !volumesAfterLighting;
    setup.runsToEnd = conditions.runsToEnd;
    setup.work = scene.work;
    setup.readOnlyDepth = conditions.readOnlyDepth;
}

}  // namespace

FrameSetup prepareFrame(const SceneSettings& scene, int width, int height, const FrameConditions& conditions) {
    const DepthConvention& depth = conditions.depth;
    FrameSetup setup;
    setup.view.pose = scene.camera ? *scene.camera : defaultCameraPath(scene.terrain, scene.timeSeconds);
    setup.view.projection = scene.projection;
    setup.view.aspect = float(width) / float(height);
    setup.view.depthMapping = depth.mapping;
    setup.hour = scene.hour ? *scene.hour : hourAtTime(scene.timeSeconds);
    setup.sky = skyAtHour(setup.hour);
    setup.wedge = computeTerrainWedge(setup.view, scene.grid, scene.viewDistance);
    setup.cameraAboveWater = setup.view.pose.position.y >= double(scene.water.level);
    setup.reflectionsActive = scene.water.reflections && setup.cameraAboveWater;
    // Only the table's divisors: anything else (a scene built in code) draws at full resolution.
    for (const ReflectionResolution& resolution : kReflectionResolutions)
        if (resolution.divisor == scene.water.reflectionDivisor) setup.reflectionDivisor = resolution.divisor;
    setup.vegetationEnabled = scene.vegetation.enabled;

    FrameData& d = setup.data;
    d.viewProjection = setup.view.viewProjection();
    d.inverseViewProjection = glm::inverse(d.viewProjection);
    d.cameraPosition = glm::vec4(glm::vec3(setup.view.pose.position), 1.0f);
    d.sunDirection = glm::vec4(setup.sky.sunDirection, setup.sky.sunDirection.y);
    d.sunRadiance = glm::vec4(setup.sky.sunRadiance, 0.0f);
    d.skyZenith = glm::vec4(setup.sky.skyZenith, 1.0f);
    d.skyHorizon = glm::vec4(setup.sky.skyHorizon, 0.0f);
    d.groundAmbient = glm::vec4(setup.sky.groundAmbient, 0.0f);
    d.terrainShape = glm::vec4(scene.terrain.frequency, scene.terrain.amplitude, scene.terrain.baseHeight,
                               float(std::clamp(scene.terrain.octaves, 0, kMaxNoiseOctaves)));
    d.terrainGrid = glm::vec4(setup.wedge.centralAzimuth, setup.wedge.halfWidth,
                              scene.grid.firstRingRadius, setup.wedge.ringRatio);
    d.terrainGridCounts = glm::vec4(float(scene.grid.rings), float(scene.grid.segments), scene.fogStart,
                                    scene.viewDistance);
    d.depthRange = glm::vec4(scene.projection.nearPlane, scene.projection.farPlane,
                             float(scene.timeSeconds), scene.exposure);
    d.depthConvention = depth.frameData();
    d.water = glm::vec4(scene.water.level, scene.water.absorption, scene.water.rippleStrength,
                        setup.reflectionsActive ? float(OASIS_WATER_REFLECTIONS_FLAG) : 0.0f);
    d.waterTint = glm::vec4(scene.water.tint, scene.water.fresnelF0);
    // The flutter phase grows with time; wrapped here in double, it stays exact after days.
    const double kTwoPi = 6.283185307179586;
    float wind = std::clamp(scene.vegetation.windStrength, 0.0f, VegetationSettings::kMaxWindStrength);
    d.vegetation = glm::vec4(wind, float(std::fmod(scene.timeSeconds * 2.3, kTwoPi)), 0.0f, 0.0f);
    d.screen = glm::vec4(float(width), float(height), 1.0f / float(width), 1.0f / float(height));
    d.targetScale = glm::vec4(1.0f, 1.0f, 0.0f, 0.0f);  // the frame's own targets (the renderer's reflection block differs)
    for (glm::vec4& cell : d.plantDrawnBounds) cell = glm::vec4(0.0f, 0.0f, 1.0f, 1.0f);  // whole cells
    // Noise origins around the camera, in double: see shaders/common/noise.glsl.
    glm::dvec2 cameraXZ(setup.view.pose.position.x, setup.view.pose.position.z);
    NoiseOrigins terrain = terrainNoiseOrigins(scene.terrain, cameraXZ);
    std::copy(terrain.begin(), terrain.end(), d.terrainNoiseOrigins);
    // Detail layers: a drift joins the origin, so hours of it never cost precision.
    for (const DetailNoiseLayer& layer : kDetailNoiseLayers) {
        d.detailNoiseOrigins[layer.index] = skewedOrigin(cameraXZ * layer.scale + layer.drift * scene.timeSeconds);
        d.detailNoiseScales[layer.index / 4][layer.index % 4] = float(layer.scale);
    }

    // Sun shadows: cascades out to the view distance while the sun is above the horizon.
    setup.shadowQuality = findShadowQuality(scene.shadows.quality);
    if (!setup.shadowQuality) setup.shadowQuality = &defaultShadowQuality();
    setup.shadowsActive = scene.shadows.enabled && setup.sky.sunDirection.y > 0.0f;
    if (setup.shadowsActive) {
        setup.shadowCascades = fitShadowCascades(setup.view, setup.sky.sunDirection, *setup.shadowQuality,
                                                 scene.viewDistance, terrainHeightBounds(scene.terrain),
                                                 conditions.casterDepth);
        const ShadowCascades& cascades = setup.shadowCascades;
        for (int c = 0; c < OASIS_SHADOW_MAX_CASCADES; ++c) d.shadowMatrices[c] = cascades.matrices[size_t(c)];
        d.shadow = glm::vec4(1.0f, float(cascades.count), cascades.fadeStart, cascades.fadeEnd);
        d.shadowTexel = cascades.texel;
        d.shadowDepthRange = cascades.depthRange;
    } else {
        for (glm::mat4& matrix : d.shadowMatrices) matrix = glm::mat4(1.0f);
        d.shadow = glm::vec4(0.0f);
        d.shadowTexel = glm::vec4(0.0f);
        d.shadowDepthRange = glm::vec4(1.0f);
    }

    std::vector<WorldPointLight> world = scene.lights.list
        ? *scene.lights.list
        : scenePointLights(scene.lights.count, scene.timeSeconds, scene.terrain, scene.water.level);
    setup.lights.reserve(world.size());
    for (const WorldPointLight& light : world)
        setup.lights.push_back(PointLight{glm::vec4(glm::vec3(light.position - setup.view.pose.position), light.radius),
                                          glm::vec4(light.colour, light.intensity)});
    applyConditions(setup, scene, conditions);
    preparePlants(setup, scene, height, conditions);
    return setup;
}

}  // namespace oasis
