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
    for (const ProgramVariant& variant : programVariants()) names.push_back(variant.name);
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
// where storage blocks exist (render/renderer.cpp, common/water_bounds.glsl).
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
    for (const ProgramVariant& variant : programVariants()) {
        const auto& d = variant.defines;
        bool bounded = std::find(d.begin(), d.end(), "MIRRORED") != d.end() ||
                       std::find(d.begin(), d.end(), "WATER_BOUNDED") != d.end() || variant.name == "water.mask";
        if (bounded) names.push_back(variant.name);
    }
    return names;
}

INSTANTIATE_TEST_SUITE_P(Shaders, WaterBoundedVariant, ::testing::ValuesIn(waterBoundedVariantNames()), testName);

TEST(ShaderVariants, TableCoversEveryShaderFile) {
    // Every .vert/.frag/.comp in shaders/ is used by some variant: no shader escapes compilation.
    std::set<std::string> used;
    for (const ProgramVariant& variant : programVariants())
        for (const std::string& file : variant.stageFiles()) used.insert(file);
    for (const auto& entry : std::filesystem::directory_iterator(findShaderDirectory())) {
        std::string ext = entry.path().extension().string();
        if (ext == ".vert" || ext == ".frag" || ext == ".comp")
            EXPECT_TRUE(used.count(entry.path().filename().string())) << entry.path() << " is in no variant";
    }
}

TEST(ShaderVariants, ComputeVariantsHaveOnlyAComputeStage) {
    int computePrograms = 0;
    for (const ProgramVariant& variant : programVariants()) {
        if (!variant.isCompute()) continue;
        ++computePrograms;
        EXPECT_TRUE(variant.vertexFile.empty() && variant.fragmentFile.empty()) << variant.name;
    }
    EXPECT_GE(computePrograms, 3);  // the turtle interpretation's three passes
}

}  // namespace
}  // namespace oasis
