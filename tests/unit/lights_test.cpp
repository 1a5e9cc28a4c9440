// Covers the point lights without GL: the light struct's bytes, the path choice and the UBO layout
// (render/light_paths.h), the light volume mesh and the scene's lights (scene/point_lights.h),
// camera-relative positions in prepareFrame, context defines with values in the shader library,
// and --lights / --lights-path.
#include <gtest/gtest.h>

#include <cstddef>
#include <map>
#include <set>

#include "cli/options.h"
#include "render/frame_setup.h"
#include "render/light_data.h"
#include "render/light_method.h"
#include "render/light_paths.h"
#include "render/shader_library.h"
#include "render/shader_variants.h"
#include "scene/point_lights.h"

namespace oasis {
namespace {

TEST(LightData, TwoVec4sWithTheSameBytesInStd140AndStd430) {
    EXPECT_EQ(sizeof(PointLight), 32u);
    EXPECT_EQ(offsetof(PointLight, positionRadius), 0u);
    EXPECT_EQ(offsetof(PointLight, colourIntensity), 16u);
}

TEST(LightPaths, NamesParseBackAndDefinesDiffer) {
    std::set<std::string> defines;
    for (LightsPath path : {LightsPath::Ssbo, LightsPath::SsboCount, LightsPath::Ubo}) {
        LightsPath parsed;
        ASSERT_TRUE(parseLightsPath(lightsPathName(path), parsed));
        EXPECT_EQ(parsed, path);
        defines.insert(lightsPathDefine(path));
        EXPECT_EQ(lightsVariantSuffix(path), std::string(".lights-") + lightsPathName(path));
    }
    EXPECT_EQ(defines.size(), 3u);
    LightsPath unused;
    EXPECT_FALSE(parseLightsPath("uniform", unused));
}

TEST(LightPaths, ChosenFromCapabilitiesOrForcedWithAFallback) {
    EXPECT_EQ(chooseLightsPath(true).path, LightsPath::Ssbo);
    EXPECT_EQ(chooseLightsPath(false).path, LightsPath::Ubo);
    EXPECT_NE(chooseLightsPath(false).reason.find("no GL 4.3"), std::string::npos);
    LightsPathChoice forced = chooseLightsPath(true, LightsPath::SsboCount);
    EXPECT_EQ(forced.path, LightsPath::SsboCount);
    EXPECT_NE(forced.reason.find("forced"), std::string::npos);
    EXPECT_EQ(chooseLightsPath(true, LightsPath::Ubo).path, LightsPath::Ubo);
    LightsPathChoice refused = chooseLightsPath(false, LightsPath::Ssbo);
    EXPECT_EQ(refused.path, LightsPath::Ubo);
    EXPECT_NE(refused.reason.find("ssbo was asked for"), std::string::npos) << refused.reason;
}

TEST(LightMethod, TiledOnlyWithComputeAndStorageLightsElseVolumesSayingWhy) {
    LightMethodChoice tiled = chooseLightMethod(true, LightMethod::Tiled, "present", LightsPath::SsboCount);
    EXPECT_EQ(tiled.method, LightMethod::Tiled);
    EXPECT_EQ(chooseLightMethod(true, LightMethod::Tiled, "present", LightsPath::Ssbo).method, LightMethod::Tiled);
    LightMethodChoice noCompute = chooseLightMethod(false, LightMethod::Tiled, "no GL 4.3", LightsPath::Ssbo);
    EXPECT_EQ(noCompute.method, LightMethod::Volumes);
    EXPECT_NE(noCompute.reason.find("no GL 4.3"), std::string::npos) << noCompute.reason;
    // The UBO path stands for a driver whose storage buffers break: tiled must not bring them back.
    LightMethodChoice ubo = chooseLightMethod(true, LightMethod::Tiled, "present", LightsPath::Ubo);
    EXPECT_EQ(ubo.method, LightMethod::Volumes);
    EXPECT_NE(ubo.reason.find("ubo path"), std::string::npos) << ubo.reason;
    EXPECT_EQ(chooseLightMethod(true, std::nullopt, "present", LightsPath::Ubo).method, LightMethod::Volumes);
    EXPECT_EQ(chooseLightMethod(true, std::nullopt, "present", LightsPath::Ssbo).method, kDefaultLightMethod);
}

TEST(LightPaths, UboLayoutFromTheBlockSizeLimit) {
    UboLightLayout common = uboLightLayout(65536, 14);
    EXPECT_EQ(common.capacity, 2048);
    EXPECT_EQ(common.blocks, 2);
    EXPECT_EQ(common.maxLights(), 4096);
    UboLightLayout small = uboLightLayout(16384, 12);  // the GL minimum block size
    EXPECT_EQ(small.capacity, 512);
    EXPECT_EQ(small.blocks, 8);
    UboLightLayout odd = uboLightLayout(1000, 14, 100);  // 31 lights fit; rounded down to 24 (256-byte blocks)
    EXPECT_EQ(odd.capacity, 24);
    EXPECT_EQ(odd.blocks, 5);
    UboLightLayout cramped = uboLightLayout(65536, 3);  // one block left besides frame and count
    EXPECT_EQ(cramped.blocks, 1);
    EXPECT_EQ(cramped.maxLights(), 2048);  // the rest would be dropped, with a warning
}

TEST(LightVolumeMesh, ClosedOutwardAndContainsTheUnitSphere) {
    std::vector<glm::vec3> mesh = lightVolumeMesh();
    ASSERT_EQ(mesh.size(), 240u);  // 80 triangles
    std::map<std::pair<std::tuple<float, float, float>, std::tuple<float, float, float>>, int> directed;
    auto key = [](glm::vec3 v) { return std::tuple<float, float, float>(v.x, v.y, v.z); };
    for (size_t i = 0; i < mesh.size(); i += 3) {
        glm::dvec3 a(mesh[i]), b(mesh[i + 1]), c(mesh[i + 2]);
        glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
        EXPECT_GT(glm::dot(n, (a + b + c) / 3.0), 0.0) << "triangle " << i / 3 << " faces inwards";
        EXPECT_GE(glm::dot(n, a), 1.0) << "triangle " << i / 3 << " cuts into the unit sphere";
        EXPECT_LT(glm::dot(n, a), 1.1) << "triangle " << i / 3 << " is needlessly far out";
        for (int e = 0; e < 3; ++e) ++directed[{key(mesh[i + e]), key(mesh[i + (e + 1) % 3])}];
    }
    for (const auto& [edge, count] : directed) {
        EXPECT_EQ(count, 1) << "an edge is used twice in one direction";
        EXPECT_EQ(directed.count({edge.second, edge.first}), 1u) << "an open edge";
    }
}

TEST(ScenePointLights, StablePerIndexAboveTheGroundAndAnimated) {
    TerrainShape terrain;
    std::vector<WorldPointLight> many = scenePointLights(500, 3.0, terrain, 0.0f);
    std::vector<WorldPointLight> few = scenePointLights(20, 3.0, terrain, 0.0f);
    ASSERT_EQ(many.size(), 500u);
    ASSERT_EQ(few.size(), 20u);
    EXPECT_TRUE(scenePointLights(0, 3.0, terrain, 0.0f).empty());
    for (size_t i = 0; i < few.size(); ++i) EXPECT_EQ(few[i].position, many[i].position) << "light " << i;
    std::vector<WorldPointLight> later = scenePointLights(500, 4.0, terrain, 0.0f);
    int moved = 0;
    for (size_t i = 0; i < many.size(); ++i) {
        const WorldPointLight& light = many[i];
        double ground = std::max(double(terrainHeight(terrain, glm::vec2(glm::dvec2(light.position.x, light.position.z))).x), 0.0);
        EXPECT_GE(light.position.y - ground, 0.5) << "light " << i << " is in the ground";
        EXPECT_LE(light.position.y - ground, 7.0) << "light " << i << " floats too high";
        EXPECT_GT(light.radius, 0.0f);
        EXPECT_GT(light.intensity, 0.0f);
        moved += glm::distance(light.position, later[i].position) > 0.1;
    }
    EXPECT_EQ(moved, 500) << "every light moves with time";
}

TEST(ScenePointLights, CameraRelativePositionsAreSubtractedInDouble) {
    SceneSettings scene;
    scene.camera = CameraPose{glm::dvec3(1.0e7 + 0.25, 12.0, -3.0e6), 0.0f, 0.0f};
    WorldPointLight light;
    light.position = glm::dvec3(1.0e7 + 1.75, 13.0, -3.0e6 - 0.5);
    light.radius = 5.0f;
    scene.lights.list = std::vector<WorldPointLight>{light};
    FrameSetup frame = prepareFrame(scene, 64, 64);
    ASSERT_EQ(frame.lights.size(), 1u);
    EXPECT_EQ(frame.lights[0].positionRadius, glm::vec4(1.5f, 1.0f, -0.5f, 5.0f));
    scene.lights.list.reset();
    scene.lights.count = 7;
    EXPECT_EQ(prepareFrame(scene, 64, 64).lights.size(), 7u);
}

TEST(ShaderLibraryDefines, ContextDefinesWithValuesReachEveryStage) {
    ShaderLibrary library(OASIS_SOURCE_SHADER_DIR);
    library.setContextDefines({"LIGHTS_UBO_CAPACITY 77", "LIGHTS_UBO_BLOCKS 3"});
    const ProgramVariant* variant = findProgramVariant("light.shade.lights-ubo");
    ASSERT_NE(variant, nullptr);
    for (const std::string& file : variant->stageFiles()) {
        PreprocessedShader shader;
        std::string error;
        ASSERT_TRUE(library.preprocess(file, variant->defines, shader, error)) << error;
        EXPECT_NE(shader.text.find("#define LIGHTS_UBO\n"), std::string::npos) << file;
        EXPECT_NE(shader.text.find("#define LIGHTS_UBO_CAPACITY 77\n"), std::string::npos) << file;
        EXPECT_NE(shader.text.find("#define LIGHTS_UBO_BLOCKS 3\n"), std::string::npos) << file;
        // The context's value comes before lights.glsl's fallback, which is guarded by #ifndef.
        EXPECT_LT(shader.text.find("#define LIGHTS_UBO_CAPACITY 77"), shader.text.find("#ifndef LIGHTS_UBO_CAPACITY"));
    }
}

TEST(LightOptions, CountAndPathParsedAndCheckedOnEveryCommand) {
    for (std::string command : {"render", "compare", "window"}) {
        ParseResult r = parseCommandLine({command, "--lights", "4096", "--lights-path", "ssbo-count"});
        ASSERT_TRUE(r.ok) << r.error;
        EXPECT_EQ(r.options.scene.lights, 4096);
        ASSERT_TRUE(r.options.scene.lightsPath.has_value());
        EXPECT_EQ(*r.options.scene.lightsPath, LightsPath::SsboCount);
    }
    ParseResult none = parseCommandLine({"render"});
    EXPECT_EQ(none.options.scene.lights, 0);
    EXPECT_FALSE(none.options.scene.lightsPath.has_value());
    for (std::vector<std::string> bad : {std::vector<std::string>{"--lights", "4097"}, {"--lights", "-1"},
                                         {"--lights", "many"}, {"--lights-path", "uniform"}}) {
        ParseResult r = parseCommandLine(bad);
        EXPECT_FALSE(r.ok) << bad[0] << " " << bad[1];
        EXPECT_NE(r.error.find(bad[0]), std::string::npos) << r.error;
    }
    EXPECT_NE(usage(Command::Compare).find("--lights-path"), std::string::npos);
}

}  // namespace
}  // namespace oasis
