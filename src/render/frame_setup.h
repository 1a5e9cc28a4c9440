// From scene settings (time, camera, hour) to everything a frame needs: the camera view, the
// sky state, the terrain wedge and the FrameData uploaded to the GPU. No GL here.
#pragma once
#include <optional>

#include "render/frame_data.h"
#include "scene/camera.h"
#include "scene/sky.h"
#include "scene/terrain.h"
#include "scene/vegetation.h"

namespace oasis {

// The water plane and its look; every field is a run-time setting (panel and CLI).
struct WaterSettings {
    float level = 0.0f;                                // world y of the plane
    float absorption = 0.09f;                          // per world unit of water crossed (red channel)
    float rippleStrength = 1.0f;                       // 0 = a still mirror
    glm::vec3 tint{0.02f, 0.11f, 0.10f};               // what deep water's scattered light looks like
    float fresnelF0 = 0.02f;                           // reflectance looking straight down (water: ~0.02)
    bool reflections = true;                           // the mirrored scene; off: the sky alone is reflected
};

struct SceneSettings {
    double timeSeconds = 0.0;
    std::optional<double> hour;          // overrides the clock's hour of day
    std::optional<CameraPose> camera;    // overrides the default flight
    TerrainShape terrain;
    TerrainGridDensity grid;
    Projection projection;
    float viewDistance = 4000.0f;        // where the terrain grid ends, fully fogged
    float fogStart = 350.0f;
    float exposure = 1.0f;
    WaterSettings water;
    VegetationSettings vegetation;
};

struct FrameSetup {
    CameraView view;
    double hour = 0.0;
    SkyState sky;
    TerrainWedge wedge;
    bool cameraAboveWater = true;   // at the level counts as above: the plane is seen edge-on
    bool reflectionsActive = true;  // reflections on and the camera above the water
    bool vegetationEnabled = true;
    FrameData data;
};

FrameSetup prepareFrame(const SceneSettings& scene, int width, int height);

}  // namespace oasis
