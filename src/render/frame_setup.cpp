// Builds a frame's CPU-side state and its uniform block contents.
#include "render/frame_setup.h"

#include "common/shared_constants.glsl"

namespace oasis {

FrameSetup prepareFrame(const SceneSettings& scene, int width, int height) {
    FrameSetup setup;
    setup.view.pose = scene.camera ? *scene.camera : defaultCameraPath(scene.terrain, scene.timeSeconds);
    setup.view.projection = scene.projection;
    setup.view.aspect = float(width) / float(height);
    setup.hour = scene.hour ? *scene.hour : hourAtTime(scene.timeSeconds);
    setup.sky = skyAtHour(setup.hour);
    setup.wedge = computeTerrainWedge(setup.view, scene.grid, scene.viewDistance);
    setup.cameraAboveWater = setup.view.pose.position.y >= double(scene.water.level);
    setup.reflectionsActive = scene.water.reflections && setup.cameraAboveWater;

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
                               float(scene.terrain.octaves));
    d.terrainGrid = glm::vec4(setup.wedge.centralAzimuth, setup.wedge.halfWidth,
                              scene.grid.firstRingRadius, setup.wedge.ringRatio);
    d.terrainGridCounts = glm::vec4(float(scene.grid.rings), float(scene.grid.segments), scene.fogStart,
                                    scene.viewDistance);
    d.depthRange = glm::vec4(scene.projection.nearPlane, scene.projection.farPlane,
                             float(scene.timeSeconds), scene.exposure);
    d.water = glm::vec4(scene.water.level, scene.water.absorption, scene.water.rippleStrength,
                        setup.reflectionsActive ? float(OASIS_WATER_REFLECTIONS_FLAG) : 0.0f);
    d.waterTint = glm::vec4(scene.water.tint, scene.water.fresnelF0);

    std::vector<WorldPointLight> world = scene.lights.list
        ? *scene.lights.list
        : scenePointLights(scene.lights.count, scene.timeSeconds, scene.terrain, scene.water.level);
    setup.lights.reserve(world.size());
    for (const WorldPointLight& light : world)
        setup.lights.push_back(PointLight{glm::vec4(glm::vec3(light.position - setup.view.pose.position), light.radius),
                                          glm::vec4(light.colour, light.intensity)});
    return setup;
}

}  // namespace oasis
