// Every shader program variant oasis can request, compiled and linked by glslang with OpenGL
// semantics (no GL context): a variant that does not compile fails here naming file:line.
// Broken-shader and line-number cases are in glslang_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <unistd.h>

#include "glslang_compiler.h"

namespace oasis {
namespace {

using namespace glslang_test;

class EveryVariant : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryVariant, CompilesAndLinksWithGlslang) {
    std::string directory = findShaderDirectory();
    ASSERT_FALSE(directory.empty()) << "shader directory not found";
    ShaderLibrary library(directory);
    const ProgramVariant* variant = findProgramVariant(GetParam());
    ASSERT_NE(variant, nullptr);
    std::string log;
    EXPECT_TRUE(compileVariant(library, *variant, log)) << variant->name << ":\n" << log;
}

std::vector<std::string> variantNames() {
    std::vector<std::string> names;
    for (const ProgramVariant& variant : everyProgramVariant()) names.push_back(variant.name);
    return names;
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = info.param;
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Shaders, EveryVariant, ::testing::ValuesIn(variantNames()), testName);

// The variants that record or clip to the visible water, with the context define that turns it on
// where storage blocks exist (frame/renderer_choices.cpp, common/water_bounds.glsl).
class WaterBoundedVariant : public ::testing::TestWithParam<std::string> {};

TEST_P(WaterBoundedVariant, CompilesAndLinksWithGlslang) {
    std::string directory = findShaderDirectory();
    ASSERT_FALSE(directory.empty()) << "shader directory not found";
    ShaderLibrary library(directory);
    library.setContextDefines({"WATER_BOUNDS 1"});
    const ProgramVariant* variant = findProgramVariant(GetParam());
    ASSERT_NE(variant, nullptr);
    std::string log;
    EXPECT_TRUE(compileVariant(library, *variant, log)) << variant->name << " with WATER_BOUNDS:\n" << log;
}

std::vector<std::string> waterBoundedVariantNames() {
    std::vector<std::string> names;
    for (const ProgramVariant& variant : everyProgramVariant()) {
        const auto& d = variant.defines;
        bool bounded = std::find(d.begin(), d.end(), "MIRRORED") != d.end() ||
                       std::find(d.begin(), d.end(), "WATER_BOUNDED") != d.end() || variant.name == "water.mask";
        if (bounded) names.push_back(variant.name);
    }
    return names;
}

INSTANTIATE_TEST_SUITE_P(Shaders, WaterBoundedVariant, ::testing::ValuesIn(waterBoundedVariantNames()), testName);

// The OpenGL ES dialects (--api gles): every variant as GLSL ES 3.20 and as 3.10 (its compute
// stages with GL_EXT_gpu_shader5 for `precise`, as on llvmpipe's ES 3.1), and every variant the ES
// 3.0 tier can request (no compute, no storage blocks) as GLSL ES 3.00, from the same files with the
// dialect's version line, precisions and defines. glslang 12 does not know
// GL_EXT_clip_cull_distance, so these use the dialect without it (the water-plane clip by
// discard) and without GL_EXT_depth_clamp (the shadow casters flattened); the extension's spelling is compiled by the real driver in the gpu-gles suite.
struct EsCase {
    std::string variant;
    int minor;  // ES 3.minor
};

class EsVariant : public ::testing::TestWithParam<EsCase> {};

TEST_P(EsVariant, CompilesAndLinksWithGlslang) {
    std::string directory = findShaderDirectory();
    ASSERT_FALSE(directory.empty()) << "shader directory not found";
    int minor = GetParam().minor;
    ShaderLibrary library(directory, glslDialectForEs(3, minor, false, false, minor == 1 ? "GL_EXT_gpu_shader5" : ""));
    library.setContextDefines({"LIGHTS_UBO_CAPACITY 256", "LIGHTS_UBO_BLOCKS 8"});
    const ProgramVariant* variant = findProgramVariant(GetParam().variant);
    ASSERT_NE(variant, nullptr);
    PreprocessedShader text;
    std::string error;
    ASSERT_TRUE(library.preprocess(variant->stageFiles()[0], variant->defines, text, error)) << error;
    ASSERT_EQ(text.text.rfind("#version 3" + std::to_string(minor) + "0 es\n", 0), 0u);
    std::string log;
    EXPECT_TRUE(compileVariant(library, *variant, log)) << variant->name << " as GLSL ES 3." << minor << ":\n" << log;
}

bool usesStorageBlocks(const ProgramVariant& variant) {
    const auto& d = variant.defines;
    for (const char* define : {"LIGHTS_SSBO", "LIGHTS_SSBO_COUNT", "LIGHTS_TILED"})
        if (std::find(d.begin(), d.end(), define) != d.end()) return true;
    return variant.isCompute();
}

std::vector<EsCase> esCases() {
    std::vector<EsCase> cases;
    for (const ProgramVariant& variant : everyProgramVariant()) {
        cases.push_back({variant.name, 2});
        cases.push_back({variant.name, 1});
        if (!usesStorageBlocks(variant)) cases.push_back({variant.name, 0});
    }
    return cases;
}

std::string esTestName(const ::testing::TestParamInfo<EsCase>& info) {
    std::string name = info.param.variant + "_es3" + std::to_string(info.param.minor) + "0";
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Shaders, EsVariant, ::testing::ValuesIn(esCases()), esTestName);

// The ES header: version, dialect defines and precisions, no desktop extension lines (a compute
// stage or a storage-block light path below GLSL 4.30 gets ARB lines on desktop, never on ES).
TEST(EsDialect, HeaderHasVersionDefinesAndPrecisions) {
    GlslDialect es32 = glslDialectForEs(3, 2, true, true);
    EXPECT_EQ(es32.versionLine, "#version 320 es");
    EXPECT_TRUE(es32.es());
    ASSERT_EQ(es32.extensionLines.size(), 1u);
    EXPECT_EQ(es32.extensionLines[0], "#extension GL_EXT_clip_cull_distance : enable");
    EXPECT_EQ(computeExtensionLines(es32), "");
    EXPECT_EQ(std::find(es32.defines.begin(), es32.defines.end(), "OASIS_NO_DEPTH_CLAMP 1"), es32.defines.end());
    GlslDialect es30 = glslDialectForEs(3, 0, false, false);
    EXPECT_EQ(es30.versionLine, "#version 300 es");
    EXPECT_TRUE(es30.extensionLines.empty());
    EXPECT_NE(std::find(es30.defines.begin(), es30.defines.end(), "OASIS_NO_CLIP_DISTANCE 1"), es30.defines.end());
    EXPECT_NE(std::find(es30.defines.begin(), es30.defines.end(), "OASIS_NO_DEPTH_CLAMP 1"), es30.defines.end());
    EXPECT_FALSE(GlslDialect{}.es());
    ShaderLibrary library(findShaderDirectory(), es30);
    PreprocessedShader text;
    std::string error;
    ASSERT_TRUE(library.preprocess("terrain.vert", {"MIRRORED"}, text, error)) << error;
    size_t precision = text.text.find("precision highp float;");
    size_t define = text.text.find("#define MIRRORED");
    ASSERT_NE(precision, std::string::npos);
    EXPECT_LT(define, precision);  // #defines first, then the precisions, then the code
    EXPECT_NE(text.text.find("precision highp usampler2D;"), std::string::npos);
    EXPECT_NE(text.text.find("#define OASIS_NO_CLIP_DISTANCE 1"), std::string::npos);  // the clip by discard
    EXPECT_EQ(text.text.find("GL_ARB_"), std::string::npos);
    // ES 3.1: compute stages enable the gpu_shader5 extension the context has, for `precise`.
    EXPECT_EQ(computeExtensionLines(glslDialectForEs(3, 1, true, true, "GL_OES_gpu_shader5")),
              "#extension GL_OES_gpu_shader5 : require\n");
    EXPECT_EQ(computeExtensionLines(glslDialectForEs(3, 2, true, true, "GL_EXT_gpu_shader5")), "") << "core in 3.20";
}

// Without EXT_/OES_gpu_shader5 GLSL ES 3.10 has no `precise`: the interpreter does not compile
// there, which is why gl::Capabilities::computeAvailable sends such a context to the CPU path.
TEST(EsDialect, Es31InterpreterNeedsGpuShader5) {
    ShaderLibrary library(findShaderDirectory(), glslDialectForEs(3, 1, false, false));
    const ProgramVariant* variant = findProgramVariant("lsystem.local");
    ASSERT_NE(variant, nullptr);
    std::string log;
    EXPECT_FALSE(compileVariant(library, *variant, log));
    EXPECT_NE(log.find("precise"), std::string::npos) << log;
}

TEST(ShaderVariants, TableCoversEveryShaderFile) {
    // Every .vert/.frag/.comp in shaders/ is used by some variant: no shader escapes compilation.
    std::set<std::string> used;
    for (const ProgramVariant& variant : everyProgramVariant())
        for (const std::string& file : variant.stageFiles()) used.insert(file);
    for (const auto& entry : std::filesystem::directory_iterator(findShaderDirectory())) {
        std::string ext = entry.path().extension().string();
        if (ext == ".vert" || ext == ".frag" || ext == ".comp")
            EXPECT_TRUE(used.count(entry.path().filename().string())) << entry.path() << " is in no variant";
    }
}

TEST(ShaderVariants, ComputeVariantsHaveOnlyAComputeStage) {
    int computePrograms = 0;
    for (const ProgramVariant& variant : everyProgramVariant()) {
        if (!variant.isCompute()) continue;
        ++computePrograms;
        EXPECT_TRUE(variant.vertexFile.empty() && variant.fragmentFile.empty()) << variant.name;
    }
    EXPECT_GE(computePrograms, 3);  // the turtle interpretation's three passes
}

}  // namespace
}  // namespace oasis
