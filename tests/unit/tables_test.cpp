// Covers the tables: G-buffer layouts (gbuffer_layout.h), debug views (debug_views.h) and program variants (shader_variants.h) with their shader files.
#include <gtest/gtest.h>

#include "render/light_paths.h"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "debug/debug_views.h"
#include "passes/pass.h"
#include "render/gbuffer_layout.h"
#include "render/shader_library.h"
#include "render/shader_variants.h"

namespace oasis {
namespace {

// Bytes per pixel of a sized internal format, from the GL specification's format tables.
int formatBytes(GLenum internalFormat) {
    switch (internalFormat) {
        case GL_RGBA8: return 4;
        case GL_RGBA16F: return 8;
        case GL_RGBA32F: return 16;
        case GL_DEPTH24_STENCIL8: return 4;
        default: return -1;
    }
}

std::string readText(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
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
    EXPECT_EQ(findGBufferLayout("nope"), nullptr);
    EXPECT_EQ(findGBufferLayout(""), nullptr);
    EXPECT_EQ(findGBufferLayout("Standard"), nullptr);  // names are exact
    EXPECT_EQ(defaultGBufferLayout().name, "standard");
    EXPECT_EQ(&defaultGBufferLayout(), findGBufferLayout("standard"));
}

TEST(GBufferLayoutTable, BytesPerPixel) {
    // full: four RGBA32F (16 each) + D24S8 (4); standard: RGBA8 + RGBA16F + RGBA32F + RGBA8 + D24S8.
    ASSERT_NE(findGBufferLayout("full"), nullptr);
    ASSERT_NE(findGBufferLayout("standard"), nullptr);
    EXPECT_EQ(findGBufferLayout("full")->bytesPerPixel(), 68);
    EXPECT_EQ(findGBufferLayout("standard")->bytesPerPixel(), 36);
}

TEST(GBufferLayoutTable, FormatBytesAgreeWithInternalFormats) {
    const Target gbuffer[] = {Target::Albedo, Target::Normal, Target::Position, Target::Info, Target::DepthStencil};
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
    // Positions are camera-relative floats in every layout (the precision argument in gbuffer_layout.cpp).
    for (const GBufferLayout& layout : gbufferLayouts())
        EXPECT_EQ(layout.position.internalFormat, GLenum(GL_RGBA32F)) << layout.name;
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
        // light-volumes counts the lights at the G-buffer's positions; vegetation masks by its flags.
        bool gbuffer = view.name == "albedo" || view.name == "normal" || view.name == "position" ||
                       view.name == "info" || view.name == "vegetation" || view.name == "light-volumes";
        EXPECT_EQ(readsGBuffer(view), gbuffer) << view.name;
    }
}

TEST(DebugViewTable, EachViewHasItsProgramAndItsRemappingExistsInTheShader) {
    std::string directory = findShaderDirectory();
    ASSERT_FALSE(directory.empty());
    std::string shader = readText(directory + "/debug_view.frag");
    ASSERT_FALSE(shader.empty());
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
    for (const ProgramVariant& variant : programVariants()) {
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
    EXPECT_EQ(names.size(), programVariants().size());
    EXPECT_EQ(findProgramVariant("nope"), nullptr);
}

TEST(ProgramVariantTable, EveryProgramThePassesRequestExists) {
    // Fixed names used by passes/*.cpp, and the names built by variantName() for the geometry passes.
    for (const char* name : {"floor.write", "floor.read", "gbuffer.clear", "tonemap", "lighting",
                             "lighting.mirrored", "present", "water.mask", "water.composite", "probe.height"})
        EXPECT_NE(findProgramVariant(name), nullptr) << name;
    // Surfaces: G-buffer variants, and forward ones per light path (SurfacePass::surfaceProgram).
    for (const char* surface : {"terrain", "vegetation"})
        for (Mirroring mirroring : {Mirroring::Direct, Mirroring::Mirrored}) {
            std::string gbuffer = variantName(surface, SurfaceOutput::GBuffer, mirroring);
            EXPECT_NE(findProgramVariant(gbuffer), nullptr) << gbuffer;
            for (LightsPath path : {LightsPath::Ssbo, LightsPath::SsboCount, LightsPath::Ubo}) {
                std::string forward = variantName(surface, SurfaceOutput::Forward, mirroring) + lightsVariantSuffix(path);
                EXPECT_NE(findProgramVariant(forward), nullptr) << forward;
            }
        }
    for (Mirroring mirroring : {Mirroring::Direct, Mirroring::Mirrored})
        EXPECT_NE(findProgramVariant(variantName("sky", SurfaceOutput::Forward, mirroring)), nullptr)
            << variantName("sky", SurfaceOutput::Forward, mirroring);
}

}  // namespace
}  // namespace oasis
