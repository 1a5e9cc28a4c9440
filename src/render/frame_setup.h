// From scene settings (time, camera, hour) to everything a frame needs: the camera view, the
// sky state, the terrain wedge and the FrameData uploaded to the GPU. No GL here.
#pragma once
#include <optional>

#include "render/frame_data.h"
#include "scene/camera.h"
#include "scene/sky.h"
#include "scene/terrain.h"

namespace oasis {

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
};

struct FrameSetup {
    CameraView view;
    double hour = 0.0;
    SkyState sky;
    TerrainWedge wedge;
    FrameData data;
};

FrameSetup prepareFrame(const SceneSettings& scene, int width, int height);

}  // namespace oasis
