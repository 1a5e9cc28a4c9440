// From scene settings (time, camera, hour) to everything a frame needs: the camera view, the
// sky state, the terrain wedge and the FrameData uploaded to the GPU. No GL here.
#pragma once
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "render/depth_convention.h"
#include "render/frame_data.h"
#include "render/light_data.h"
#include "render/light_method.h"
#include "render/light_paths.h"
#include "render/shadow_cascades.h"
#include "scene/camera.h"
#include "scene/point_lights.h"
#include "scene/sky.h"
#include "scene/terrain.h"
#include "scene/visible_water.h"
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
    bool reflectionBounds = true;                      // the reflection's passes clip to the visible water
    int reflectionDivisor = 1;                         // the reflection drawn at 1/divisor of the frame's size
};

// The reflection's resolutions (--reflection-resolution, the bench knob, the panel): the mirrored
// passes draw into targets of 1/divisor of the frame's width and height (rounded up), and
// ReflectionUpsamplePass reads them bilinearly into the frame's Reflection target.
struct ReflectionResolution {
    const char* name;
    int divisor;
};
inline constexpr ReflectionResolution kReflectionResolutions[] = {{"full", 1}, {"half", 2}, {"quarter", 4}};
inline constexpr const char* kReflectionResolutionNames = "full, half, quarter";
const ReflectionResolution* findReflectionResolution(const std::string& name);
const char* reflectionResolutionName(int divisor);  // "full" for a divisor not in the table

// The point lights: how many (scene/point_lights.h places and animates them) and, when forced
// (--lights-path, the panel), how shaders read them; otherwise the context's capabilities decide.
struct LightSettings {
    int count = 0;                                    // 0..kMaxLights
    std::optional<LightsPath> path;                   // forced path; empty = automatic
    std::optional<LightMethod> method;                // forced deferred light method; empty = the default
    std::optional<std::vector<WorldPointLight>> list; // replaces the generated lights (tests, tools)
};

enum class MirroredPlantCull { Auto, On, Off };
struct MirroredPlantCullMode {
    MirroredPlantCull mode;
    const char* name;
};
// One row per mode: the CLI's names, the panel's radio buttons and the bench's levels.
inline constexpr MirroredPlantCullMode kMirroredPlantCullModes[] = {
    {MirroredPlantCull::Auto, "auto"}, {MirroredPlantCull::On, "on"}, {MirroredPlantCull::Off, "off"}};
const MirroredPlantCullMode* findMirroredPlantCull(const std::string& name);

// Work a frame may save without changing its picture (bench knobs, whose reference does it all;
// tests hold the two frames equal).
struct FrameWorkSettings {
    bool fuseToneMap = true;       // --tone-map fused: the passes that write a pixel last tone-map it
    bool depthReadInPlace = true;  // --depth-read in-place: compact's lighting samples the depth target
    // --reflection-plant-cull: the reflection's plants whose mirror image can land only on dry land
    // culled on the CPU (scene/visible_water.h), at full reflection resolution only (where the
    // water's stencil is the frame's own). The bound's terrain heights cost the CPU 2.3-3.5 ms when
    // the camera has moved and 0.5-0.9 ms when it has not, against 0.7-1 ms of llvmpipe's time
    // saved: Auto culls only while the camera stands still (docs/limits.md).
    MirroredPlantCull mirroredPlantCull = MirroredPlantCull::Auto;
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
    LightSettings lights;
    FrameWorkSettings work;
    ShadowSettings shadows;
};

struct FrameSetup {
    CameraView view;
    double hour = 0.0;
    SkyState sky;
    TerrainWedge wedge;
    bool cameraAboveWater = true;   // at the level counts as above: the plane is seen edge-on
    bool reflectionsActive = true;  // reflections on and the camera above the water
    bool waterBounded = false;      // the reflection's passes clip to the visible water (the context records it)
    int reflectionDivisor = 1;      // the reflection's targets are 1/divisor of the frame's size (1: the frame's own)
    bool vegetationEnabled = true;
    bool mirroredPlantsCulled = false;  // the reflection's plant chunks culled against the dry land
    bool positionFromDepth = false;  // the layout reconstructs positions from depth
    // The scene's savings as asked for (--tone-map, --depth-read, --reflection-plant-cull): whole,
    // so a new one reaches the passes without a line here. With depth-read in place, a layout that
    // reconstructs positions lights by sampling the depth-stencil target itself, drawn without it
    // attached; else it reads DepthCopyPass's copy, made every frame.
    FrameWorkSettings work;
    // The context may depth-test against the target a draw samples (writes off): such a layout's
    // in-place lighting then shades only the surfaces too (the context's capabilities).
    bool readOnlyDepth = false;
    // The sun's shadow maps this frame: shadows on and the sun above the horizon (at night no
    // shadow pass runs). The cascades are also in `data` for the shaders.
    bool shadowsActive = false;
    const ShadowQuality* shadowQuality = nullptr;
    ShadowCascades shadowCascades;
    // The tone map is written by the passes that write each pixel's colour last (".tonemapped"
    // variants), ToneMapPass skipped: not for --stop-before, nor with the deferred light volumes
    // (they add to Radiance after LightingPass).
    bool toneMapFused = false;
    bool runsToEnd = true;  // no --stop-before: what a later pass writes need not be cleared
    FrameData data;
    std::vector<PointLight> lights;       // camera-relative positions (subtracted in double)
    int lightsDropped = 0;                // beyond the UBO path's capacity: not drawn
    LightsPath lightsPath = LightsPath::Ubo;  // from the context and the settings
    LightMethod lightMethod = LightMethod::Volumes;  // the deferred lights' method
};

// What decides a frame besides the scene (Renderer::runFrame gathers it): its targets, the
// context's paths and capabilities, the plants' atlas and the request. prepareFrame makes the
// whole FrameSetup from the scene and these at once.
struct FrameConditions {
    DepthConvention depth = standardDepthConvention();  // of the targets drawn into; the camera projects with it
    ShadowCasterDepth casterDepth = ShadowCasterDepth::Clamped;  // whether ShadowPass clamps depth (render/shadow_cascades.h)
    bool positionFromDepth = false;     // the G-buffer layout rebuilds position from depth
    bool waterBoundsAvailable = false;  // the context can record the rectangle of visible water
    bool readOnlyDepth = false;         // the context may depth-test against a target a draw samples
    LightsPath lightsPath = LightsPath::Ubo;
    int uboMaxLights = std::numeric_limits<int>::max();  // the UBO path's capacity: more are dropped
    LightMethod lightMethod = LightMethod::Volumes;
    bool deferred = false;  // the deferred pipeline, whose light volumes add to Radiance after LightingPass
    bool runsToEnd = true;  // no --stop-before
    // The plants' atlas (vegetation.vert picks a mip level by it): its cells across and down, the
    // texels of a cell (1 with no atlas), and each cell's drawn bounds where the billboards are
    // trimmed (null: whole cells). No atlas: no plants drawn.
    bool plantAtlas = false;
    int atlasColumns = 1, atlasRows = 1;
    float cellTexels = 1.0f;
    const std::vector<glm::vec4>* plantDrawnBounds = nullptr;
    // The last frame's terrain grid, where plants were drawn (null: none): the camera stands still
    // while it is this frame's (terrainGridPlacement), and the reflection's plants are culled on
    // the CPU in MirroredPlantCull::Auto then only.
    const TerrainGridPlacement* lastGrid = nullptr;
};

FrameSetup prepareFrame(const SceneSettings& scene, int width, int height, const FrameConditions& conditions = {});
// The same with the targets' depth convention (and the casters' depth) alone, as a test or tool asks.
FrameSetup prepareFrame(const SceneSettings& scene, int width, int height, const DepthConvention& depth,
                        ShadowCasterDepth casterDepth = ShadowCasterDepth::Clamped);
// Where the frame's terrain grid lies (scene/visible_water.h): what the culled reflection's plants are tested on.
TerrainGridPlacement terrainGridPlacement(const SceneSettings& scene, const FrameSetup& frame);
// Where the direct deferred lighting reads the depth a compact layout rebuilds position from
// (--depth-read): the depth-stencil target itself (true: in place) or DepthCopyPass's copy. The one
// place this is decided; the mirrored lighting always reads the copy.
bool lightingSamplesDepthTarget(const FrameSetup& frame);

}  // namespace oasis
