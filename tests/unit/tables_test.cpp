// Covers the tables: G-buffer layouts (gbuffer_layout.h), debug views (debug_views.h) and program variants (shader_variants.h) with their shader files.
#include <gtest/gtest.h>

#include "render/light_paths.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "debug/debug_views.h"
#include "passes/pass.h"
#include "render/frame_targets.h"
#include "render/gbuffer_layout.h"
#include "render/shader_library.h"
#include "render/shader_variants.h"

#include "unit_support.h"

namespace oasis {
namespace {

using namespace unittest;

// Bytes per pixel of a sized internal format, from the GL specification's format tables.
int formatBytes(GLenum internalFormat) {
    switch (internalFormat) {
        case GL_RGBA8: return 4;
        case GL_RGBA16F: return 8;
        case GL_RGBA32F: return 16;
        case GL_DEPTH24_STENCIL8: return 4;
        case GL_RG16: return 4;
        case GL_RG8: return 2;
        case 0: return 0;  // not stored
        default: return -1;
    }
}

TEST(GBufferLayoutTable, NamesUniqueAndFindable) {
    std::set<std::string> names;
    std::string joined;
    for (const GBufferLayout& layout : gbufferLayouts()) {
        EXPECT_TRUE(names.insert(layout.name).second) << "duplicate layout " << layout.name;
        EXPECT_FALSE(layout.description.empty()) << layout.name;
        EXPECT_EQ(findGBufferLayout(layout.name), &layout);
        joined += (joined.empty() ? "" : ", ") + layout.name;
    }
    EXPECT_EQ(gbufferLayoutNames(), joined);
    EXPECT_TRUE(names.count("full"));
    EXPECT_TRUE(names.count("standard"));
    EXPECT_TRUE(names.count("compact"));
    EXPECT_EQ(findGBufferLayout("nope"), nullptr);
    EXPECT_EQ(findGBufferLayout(""), nullptr);
    EXPECT_EQ(findGBufferLayout("Standard"), nullptr);  // names are exact
    EXPECT_EQ(defaultGBufferLayout().name, "compact");
    EXPECT_EQ(&defaultGBufferLayout(), findGBufferLayout("compact"));
}

TEST(GBufferLayoutTable, BytesPerPixel) {
    // full: four RGBA32F (16 each) + D24S8 (4); standard: RGBA8 + RGBA16F + RGBA32F + RGBA8 + D24S8;
    // compact: RGBA8 + RG16 + no position + RG8 + D24S8 + a D24S8 copy of depth to read it from.
    ASSERT_NE(findGBufferLayout("full"), nullptr);
    ASSERT_NE(findGBufferLayout("standard"), nullptr);
    ASSERT_NE(findGBufferLayout("compact"), nullptr);
    EXPECT_EQ(findGBufferLayout("full")->bytesPerPixel(), 68);
    EXPECT_EQ(findGBufferLayout("standard")->bytesPerPixel(), 36);
    EXPECT_EQ(findGBufferLayout("compact")->bytesPerPixel(), 18);  // + the SceneDepth copy (D24S8)
}

TEST(GBufferLayoutTable, FormatBytesAgreeWithInternalFormats) {
    const Target gbuffer[] = {Target::Albedo, Target::Normal, Target::Position, Target::Info, Target::DepthStencil,
                              Target::SceneDepth};
    for (const GBufferLayout& layout : gbufferLayouts()) {
        int sum = 0;
        for (Target target : gbuffer) {
            TargetFormat format = layout.format(target);
            EXPECT_EQ(format.bytesPerPixel, formatBytes(format.internalFormat))
                << layout.name << " " << targetName(target);
            sum += formatBytes(format.internalFormat);
        }
        EXPECT_EQ(layout.bytesPerPixel(), sum) << layout.name;
        EXPECT_EQ(layout.format(Target::Albedo).internalFormat, layout.albedo.internalFormat);
        EXPECT_EQ(layout.format(Target::Normal).internalFormat, layout.normal.internalFormat);
        EXPECT_EQ(layout.format(Target::Position).internalFormat, layout.position.internalFormat);
        EXPECT_EQ(layout.format(Target::Info).internalFormat, layout.info.internalFormat);
    }
}

// The frame targets' descriptors: a row for every target, under its own name; the G-buffer's
// colour targets take their format from the layout's row, the rest from the depth convention or
// their own, the same in every layout.
TEST(TargetDescriptors, EveryTargetHasItsRowAndItsFormatsSource) {
    std::set<std::string> names;
    for (int t = 0; t < int(Target::Count); ++t) {
        const TargetDescriptor& row = targetDescriptor(Target(t));
        EXPECT_EQ(row.target, Target(t)) << t;
        EXPECT_TRUE(names.insert(row.name).second) << row.name;
        EXPECT_NE(std::string(row.label), "");
        const bool gbufferColour = std::find(std::begin(kGBufferColourTargets),
                                             std::end(kGBufferColourTargets), Target(t)) !=
                                   std::end(kGBufferColourTargets);
        EXPECT_EQ(row.format == FormatFrom::LayoutRow, gbufferColour) << row.name;
        EXPECT_EQ(row.row != nullptr, gbufferColour) << row.name;
    }
}

TEST(GBufferLayoutTable, TargetsOutsideTheGBufferAreTheSameInEveryLayout) {
    const GBufferLayout& first = gbufferLayouts().front();
    EXPECT_EQ(first.format(Target::DepthStencil).internalFormat, GLenum(GL_DEPTH24_STENCIL8));
    EXPECT_EQ(first.format(Target::Final).internalFormat, GLenum(GL_RGBA8));  // 8-bit display colour
    EXPECT_EQ(first.format(Target::Radiance).internalFormat, GLenum(GL_RGBA16F));  // linear HDR
    EXPECT_EQ(first.format(Target::Reflection).internalFormat, GLenum(GL_RGBA16F));
    for (const GBufferLayout& layout : gbufferLayouts())
        for (Target target : {Target::DepthStencil, Target::Radiance, Target::Reflection, Target::Final}) {
            EXPECT_EQ(layout.format(target).internalFormat, first.format(target).internalFormat)
                << layout.name << " " << targetName(target);
            EXPECT_EQ(layout.format(target).bytesPerPixel, first.format(target).bytesPerPixel);
        }
    // Positions are camera-relative floats wherever they are stored (the precision argument in
    // gbuffer_layout.cpp); a layout without them reconstructs them from depth.
    for (const GBufferLayout& layout : gbufferLayouts()) {
        if (layout.stores(Target::Position)) EXPECT_EQ(layout.position.internalFormat, GLenum(GL_RGBA32F)) << layout.name;
        EXPECT_EQ(layout.positionFromDepth(), !layout.stores(Target::Position)) << layout.name;
        EXPECT_TRUE(layout.stores(Target::Albedo) && layout.stores(Target::Normal) && layout.stores(Target::Info))
            << layout.name;
    }
    EXPECT_TRUE(findGBufferLayout("compact")->positionFromDepth());
    for (const GBufferLayout& layout : gbufferLayouts())  // the copy exactly where positions come from depth
        EXPECT_EQ(layout.stores(Target::SceneDepth), layout.positionFromDepth()) << layout.name;
    EXPECT_FALSE(findGBufferLayout("standard")->positionFromDepth());
}

// Each encoding's programs exist for every G-buffer reader and writer, with its #define; the plain
// encoding's are the base programs themselves.
TEST(GBufferLayoutTable, EveryLayoutHasItsGBufferPrograms) {
    const char* bases[] = {"terrain.gbuffer", "vegetation.gbuffer.mirrored", "lighting", "lighting.mirrored",
                           "gbuffer.clear", "floor.write", "floor.read", "light.shade.lights-ubo", "debug.position",
                           "gbuffer.positions"};
    registerDebugViewPrograms();
    for (const GBufferLayout& layout : gbufferLayouts())
        for (const char* base : bases) {
            const ProgramVariant* variant = findProgramVariant(layout.program(base));
            ASSERT_NE(variant, nullptr) << layout.name << " " << base;
            std::string define = gbufferEncodingDefine(layout.encoding);
            if (define.empty()) {
                EXPECT_EQ(layout.program(base), base);
            } else {
                EXPECT_NE(std::find(variant->defines.begin(), variant->defines.end(), define), variant->defines.end())
                    << variant->name;
            }
        }
    // The stencil-marking draws and the forward surfaces never touch the G-buffer: no copies.
    EXPECT_EQ(findProgramVariant("light.mark.lights-ubo.compact"), nullptr);
    EXPECT_EQ(findProgramVariant("terrain.forward.lights-ssbo.compact"), nullptr);
}

// The cleared info texel carries the SKY flag where each encoding reads flags, and nothing else.
TEST(GBufferLayoutTable, ClearedInfoIsTheSkyFlagInTheLayoutsFlagsChannel) {
    for (const GBufferLayout& layout : gbufferLayouts()) {
        glm::vec4 cleared = layout.clearedInfo();
        EXPECT_EQ(layout.storedFlags(cleared), 1u) << layout.name;  // SURFACE_SKY
        EXPECT_FLOAT_EQ(cleared.x + cleared.y + cleared.z + cleared.w, 1.0f / 255.0f) << layout.name;
    }
    EXPECT_EQ(findGBufferLayout("standard")->storedFlags({0.0f, 0.0f, 6.0f / 255.0f, 1.0f}), 6u);
    EXPECT_EQ(findGBufferLayout("compact")->storedFlags({0.5f, 6.0f / 255.0f, 0.0f, 1.0f}), 6u);
}

// The layout's decoding of a whole surface (the shading oracle's, in double) reads each encoding's
// channels as readGBuffer does: the compact layout's intensity in albedo.a, its octahedral normal
// (the float decoding's direction), power and flags in its two info channels.
TEST(GBufferLayoutTable, StoredSurfaceReadsEachEncodingsChannels) {
    glm::dvec4 albedo(0.25, 0.5, 0.75, 0.4);
    const GBufferLayout& compact = *findGBufferLayout("compact");
    glm::vec2 e = octahedralEncode(glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f))) * 0.5f + 0.5f;
    GBufferLayout::StoredSurface c = compact.storedSurface(albedo, glm::dvec4(e, 0.0, 1.0), {12.0 / 255.0, 6.0 / 255.0, 0.0, 1.0});
    EXPECT_EQ(c.albedo, glm::dvec3(0.25, 0.5, 0.75));
    EXPECT_DOUBLE_EQ(c.specularIntensity, 0.4);
    EXPECT_DOUBLE_EQ(c.specularPower, 12.0);
    EXPECT_EQ(c.flags, 6u);
    EXPECT_NEAR(glm::length(c.normal - glm::dvec3(compact.storedNormal(glm::vec4(e, 0.0f, 1.0f)))), 0.0, 1e-6);
    EXPECT_NEAR(glm::length(c.normal), 1.0, 1e-12);  // decoded in double
    const GBufferLayout& standard = *findGBufferLayout("standard");
    GBufferLayout::StoredSurface s = standard.storedSurface(albedo, {0.0, 1.0, 0.0, 0.0}, {5.0 / 255.0, 0.3, 4.0 / 255.0, 1.0});
    EXPECT_DOUBLE_EQ(s.specularIntensity, 0.3);
    EXPECT_DOUBLE_EQ(s.specularPower, 5.0);
    EXPECT_EQ(s.flags, 4u);
    EXPECT_EQ(s.normal, glm::dvec3(0.0, 1.0, 0.0));
}

// Octahedral normals: the round trip through 16-bit unorm channels (the compact layout's RG16)
// keeps direction within 1e-4 rad over the sphere, poles, equator and fold lines included.
TEST(OctahedralNormals, RoundTripThroughSixteenBitsKeepsDirection) {
    std::vector<glm::vec3> directions = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, {0, 0, -1},
                                         {1, -1, 1}, {-1, -1, -1}, {1, 1e-7f, 0}, {0.3f, -1e-6f, -0.9f}};
    uint32_t state = 12345u;
    auto uniform = [&] { state = state * 1664525u + 1013904223u; return float(state >> 8) / float(1u << 24) * 2.0f - 1.0f; };
    for (int i = 0; i < 20000; ++i) {
        glm::vec3 v(uniform(), uniform(), uniform());
        if (glm::length(v) > 1e-3f) directions.push_back(v);
    }
    double worst = 0.0;
    for (glm::vec3 direction : directions) {
        glm::vec3 n = glm::normalize(direction);
        glm::vec2 e = octahedralEncode(n);
        ASSERT_LE(std::max(std::fabs(e.x), std::fabs(e.y)), 1.0f + 1e-6f);
        glm::vec2 stored = glm::round((e * 0.5f + 0.5f) * 65535.0f) / 65535.0f;  // RG16 unorm
        glm::vec3 back = findGBufferLayout("compact")->storedNormal(glm::vec4(stored, 0.0f, 1.0f));
        EXPECT_NEAR(glm::length(back), 1.0f, 1e-6f);
        // The angle from cross and dot in double: acos of a float dot cannot resolve below 3e-4.
        glm::dvec3 a(back), b(n);
        double angle = std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
        worst = std::max(worst, angle);
        if (angle > 1e-4) ADD_FAILURE() << "direction (" << n.x << ", " << n.y << ", " << n.z << ") off by " << angle;
    }
    std::printf("[octahedral] %zu directions, worst %.2e rad after 16-bit quantisation\n", directions.size(), worst);
}

TEST(GBufferLayoutTable, TargetNamesAreDistinct) {
    std::set<std::string> names;
    for (int t = 0; t < int(Target::Count); ++t) {
        std::string name = targetName(Target(t));
        EXPECT_NE(name, "?") << "target " << t;
        EXPECT_TRUE(names.insert(name).second) << name;
    }
    EXPECT_EQ(names.size(), size_t(Target::Count));
}

TEST(DebugViewTable, NamesUniqueAndRequiredViewsPresent) {
    std::set<std::string> names;
    for (const DebugView& view : debugViews()) {
        EXPECT_TRUE(names.insert(view.name).second) << "duplicate view " << view.name;
        EXPECT_EQ(findDebugView(view.name), &view);
        EXPECT_FALSE(view.legend.empty()) << view.name;
        EXPECT_NE(view.name, kOverviewName) << "overview is the grid of all views, not a view";
    }
    for (const char* required : {"final", "albedo", "normal", "position", "info", "depth", "stencil"})
        EXPECT_TRUE(names.count(required)) << required;
    EXPECT_EQ(debugViews().front().name, "final");  // the default --view
    EXPECT_EQ(findDebugView("nope"), nullptr);
    EXPECT_EQ(findDebugView(kOverviewName), nullptr);
}

TEST(DebugViewTable, NamesListEndsWithOverview) {
    std::string expected;
    for (const DebugView& view : debugViews()) expected += view.name + ", ";
    EXPECT_EQ(debugViewNames(), expected + "overview");
}

TEST(DebugViewTable, ReadsGBufferExactlyForTheColourTargetsAndTheViewsMaskedOrCountedByThem) {
    for (const DebugView& view : debugViews()) {
        // light-volumes counts the lights at the G-buffer's positions, shadow reads the sun's maps
        // there; vegetation masks by its flags.
        bool gbuffer = view.name == "albedo" || view.name == "normal" || view.name == "position" ||
                       view.name == "info" || view.name == "vegetation" || view.name == "light-volumes" ||
                       view.name == "shadow";
        EXPECT_EQ(readsGBuffer(view), gbuffer) << view.name;
    }
}

TEST(DebugViewTable, EachViewHasItsProgramAndItsRemappingExistsInTheShader) {
    std::string directory = findShaderDirectory();
    ASSERT_FALSE(directory.empty());
    std::string shader = readText(directory + "/debug_view.frag");
    ASSERT_FALSE(shader.empty());
    registerDebugViewPrograms();
    for (const DebugView& view : debugViews()) {
        EXPECT_EQ(debugProgramName(view), "debug." + view.name);
        const ProgramVariant* variant = findProgramVariant(debugProgramName(view));
        ASSERT_NE(variant, nullptr) << view.name;
        EXPECT_EQ(variant->fragmentFile, "debug_view.frag");
        ASSERT_EQ(variant->defines.size(), 1u) << view.name;
        EXPECT_EQ(variant->defines[0], view.remapDefine);
        EXPECT_NE(shader.find("defined(" + view.remapDefine + ")"), std::string::npos)
            << view.remapDefine << " is not handled in debug_view.frag";
    }
}

TEST(ProgramVariantTable, NamesUniqueAndEveryFileExists) {
    std::string directory = findShaderDirectory();
    ASSERT_FALSE(directory.empty()) << "no shader directory found";
    std::set<std::string> names;
    for (const ProgramVariant& variant : everyProgramVariant()) {
        EXPECT_TRUE(names.insert(variant.name).second) << "duplicate variant " << variant.name;
        EXPECT_EQ(findProgramVariant(variant.name), &variant);
        for (const std::string& file : variant.stageFiles())
            EXPECT_TRUE(std::filesystem::is_regular_file(directory + "/" + file)) << variant.name << ": " << file;
        if (variant.isCompute()) {
            EXPECT_EQ(std::filesystem::path(variant.computeFile).extension(), ".comp") << variant.name;
            EXPECT_TRUE(variant.vertexFile.empty() && variant.fragmentFile.empty()) << variant.name;
        } else {
            EXPECT_EQ(std::filesystem::path(variant.vertexFile).extension(), ".vert") << variant.name;
            EXPECT_EQ(std::filesystem::path(variant.fragmentFile).extension(), ".frag") << variant.name;
        }
        for (const std::string& define : variant.defines) EXPECT_FALSE(define.empty()) << variant.name;
    }
    EXPECT_EQ(names.size(), everyProgramVariant().size());
    EXPECT_EQ(findProgramVariant("nope"), nullptr);
}

TEST(ProgramVariantTable, EveryProgramThePassesRequestExists) {
    // Fixed names used by passes/*.cpp, and the names built by variantName() for the geometry passes.
    for (const char* name : {"floor.write", "floor.read", "gbuffer.clear", "tonemap", "lighting",
                             "lighting.mirrored", "present", "water.mask", "water.composite", "probe.height",
                             "lighting.tonemapped", "lighting.tonemapped.tiled", "sky.forward.tonemapped",
                             "water.composite.tonemapped"})
        EXPECT_NE(findProgramVariant(name), nullptr) << name;
    // Surfaces: G-buffer variants, and forward ones per light path (SurfacePass::surfaceProgram).
    for (const char* surface : {"terrain", "vegetation"})
        for (Mirroring mirroring : {Mirroring::Direct, Mirroring::Mirrored}) {
            std::string gbuffer = variantName(surface, SurfaceOutput::GBuffer, mirroring);
            EXPECT_NE(findProgramVariant(gbuffer), nullptr) << gbuffer;
            for (LightsPath path : {LightsPath::Ssbo, LightsPath::SsboCount, LightsPath::Ubo}) {
                std::string forward = variantName(surface, SurfaceOutput::Forward, mirroring) + lightsVariantSuffix(path);
                EXPECT_NE(findProgramVariant(forward), nullptr) << forward;
                // The fused tone map's variant (direct only: the mirrored scene goes to Reflection).
                std::string fused = variantName(surface, SurfaceOutput::Forward, mirroring) + ".tonemapped" +
                                    lightsVariantSuffix(path);
                EXPECT_EQ(findProgramVariant(fused) != nullptr, mirroring == Mirroring::Direct) << fused;
            }
        }
    for (Mirroring mirroring : {Mirroring::Direct, Mirroring::Mirrored})
        EXPECT_NE(findProgramVariant(variantName("sky", SurfaceOutput::Forward, mirroring)), nullptr)
            << variantName("sky", SurfaceOutput::Forward, mirroring);
}

}  // namespace
}  // namespace oasis
