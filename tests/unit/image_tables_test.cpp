// Image metrics and PNG output, the G-buffer layout and debug view tables, and shader
// preprocessing (includes, #line, error locations) without a GL context.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "debug/debug_views.h"
#include "render/gbuffer_layout.h"
#include "render/image.h"
#include "render/shader_library.h"
#include "render/shader_variants.h"

namespace oasis {
namespace {

Image filled(int w, int h, uint8_t value) {
    Image image(w, h);
    for (size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = (i % 4 == 3) ? 255 : value;
    return image;
}

TEST(Image, MetricsOfKnownDifferences) {
    Image a = filled(8, 4, 100);
    ImageDifference same = compareImages(a, a);
    EXPECT_EQ(same.psnrDb, kPsnrIdentical);
    EXPECT_EQ(same.rmse, 0.0);
    EXPECT_EQ(same.maxAbs, 0);
    Image b = a;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) b.pixel(x, y)[1] += 1;  // one channel of three off by one
    ImageDifference d = compareImages(a, b);
    EXPECT_EQ(d.maxAbs, 1);
    EXPECT_NEAR(d.rmse, std::sqrt(1.0 / 3.0), 1e-12);
    EXPECT_NEAR(d.psnrDb, 10.0 * std::log10(255.0 * 255.0 * 3.0), 1e-9);
    Image alphaOnly = a;
    alphaOnly.pixel(0, 0)[3] = 0;  // alpha is not compared
    EXPECT_EQ(compareImages(a, alphaOnly).maxAbs, 0);
    EXPECT_THROW(compareImages(a, filled(4, 8, 100)), std::invalid_argument);
}

TEST(Image, HeatmapAndFlip) {
    Image a = filled(2, 1, 0), b = a;
    b.pixel(1, 0)[0] = 255;
    Image heat = differenceHeatmap(a, b);
    EXPECT_EQ(heat.pixel(0, 0)[0], 0);
    EXPECT_EQ(heat.pixel(1, 0)[0], 255);
    EXPECT_EQ(heat.pixel(1, 0)[2], 255);  // saturated: white
    Image tall(1, 3);
    for (int y = 0; y < 3; ++y) tall.pixel(0, y)[0] = uint8_t(y);
    tall.flipRows();
    EXPECT_EQ(tall.pixel(0, 0)[0], 2);
    EXPECT_EQ(tall.pixel(0, 2)[0], 0);
}

TEST(Image, WritesPngOrSaysWhy) {
    std::string path = std::filesystem::temp_directory_path() / ("oasis-image-" + std::to_string(getpid()) + ".png");
    std::string error;
    ASSERT_TRUE(writePng(path, filled(5, 3, 7), error)) << error;
    std::ifstream in(path, std::ios::binary);
    char signature[8] = {};
    in.read(signature, 8);
    EXPECT_EQ(std::string(signature + 1, 3), "PNG");
    std::filesystem::remove(path);
    EXPECT_FALSE(writePng("/nonexistent-dir/x.png", filled(1, 1, 0), error));
    EXPECT_NE(error.find("/nonexistent-dir/x.png"), std::string::npos);
}

TEST(Tables, GBufferLayouts) {
    std::set<std::string> names;
    for (const GBufferLayout& layout : gbufferLayouts()) EXPECT_TRUE(names.insert(layout.name).second);
    ASSERT_NE(findGBufferLayout("full"), nullptr);
    EXPECT_EQ(findGBufferLayout("full")->bytesPerPixel(), 4 * 16 + 4);
    EXPECT_EQ(findGBufferLayout("standard")->bytesPerPixel(), 4 + 8 + 16 + 4 + 4);
    EXPECT_EQ(defaultGBufferLayout().name, "standard");
    EXPECT_EQ(findGBufferLayout("nope"), nullptr);
}

TEST(Tables, EveryDebugViewHasAProgramAndEveryVariantItsFiles) {
    std::set<std::string> views;
    for (const DebugView& view : debugViews()) {
        EXPECT_TRUE(views.insert(view.name).second) << view.name;
        EXPECT_NE(findProgramVariant(debugProgramName(view)), nullptr) << view.name;
        EXPECT_FALSE(view.legend.empty());
    }
    for (const char* required : {"final", "albedo", "normal", "position", "info", "depth", "stencil", "reflection"})
        EXPECT_TRUE(views.count(required)) << required;
    std::string directory = findShaderDirectory();
    ASSERT_FALSE(directory.empty());
    std::set<std::string> variants;
    for (const ProgramVariant& variant : programVariants()) {
        EXPECT_TRUE(variants.insert(variant.name).second) << variant.name;
        EXPECT_TRUE(std::filesystem::exists(directory + "/" + variant.vertexFile)) << variant.vertexFile;
        EXPECT_TRUE(std::filesystem::exists(directory + "/" + variant.fragmentFile)) << variant.fragmentFile;
    }
}

class Preprocess : public ::testing::Test {
protected:
    void SetUp() override {
        root = std::filesystem::temp_directory_path() / ("oasis-pre-" + std::to_string(getpid()));
        std::filesystem::create_directories(root / "common");
        write("common/a.glsl", "#ifndef A\n#define A\nfloat a() { return 1.0; }\n#endif\n");
        write("main.frag", "// main\n#include \"common/a.glsl\"\n#include \"common/a.glsl\"\nvoid main() {}\n");
        write("missing.frag", "// line 1\n// line 2\n#include \"common/nope.glsl\"\n");
    }
    void TearDown() override { std::filesystem::remove_all(root); }
    void write(const std::string& name, const std::string& text) { std::ofstream(root / name) << text; }
    std::filesystem::path root;
};

TEST_F(Preprocess, ExpandsIncludesWithLineDirectivesAfterVersionAndDefines) {
    ShaderLibrary library(root.string(), GlslDialect{"#version 330 core", {}});
    PreprocessedShader out;
    std::string error;
    ASSERT_TRUE(library.preprocess("main.frag", {"FOO 2", "BAR"}, out, error)) << error;
    EXPECT_EQ(out.text.rfind("#version 330 core\n#define FOO 2\n#define BAR\n#line 1 0\n", 0), 0u) << out.text;
    EXPECT_NE(out.text.find("#line 1 1\n#ifndef A"), std::string::npos);
    EXPECT_NE(out.text.find("#line 3 0\n"), std::string::npos);  // back in main.frag after the include
    ASSERT_EQ(out.files.size(), 3u);  // main, then a.glsl twice (its guard makes the second empty)
    EXPECT_EQ(out.files[0], "main.frag");
    EXPECT_EQ(out.files[1], "common/a.glsl");
}

TEST_F(Preprocess, AnnotatesMesaAndGlslangLocations) {
    PreprocessedShader shader;
    shader.files = {"main.frag", "common/a.glsl"};
    EXPECT_NE(shader.annotateLog("0:12(5): error: x").find("main.frag:12(5): error: x"), std::string::npos);
    EXPECT_NE(shader.annotateLog("ERROR: 1:7: 'y' : undeclared").find("ERROR: common/a.glsl:7: 'y'"),
              std::string::npos);
}

TEST_F(Preprocess, MissingIncludeNamesTheIncludingLine) {
    ShaderLibrary library(root.string());
    PreprocessedShader out;
    std::string error;
    EXPECT_FALSE(library.preprocess("missing.frag", {}, out, error));
    EXPECT_NE(error.find("missing.frag:3"), std::string::npos) << error;
    EXPECT_NE(error.find("common/nope.glsl"), std::string::npos) << error;
}

}  // namespace
}  // namespace oasis
