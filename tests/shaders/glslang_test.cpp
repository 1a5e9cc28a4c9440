// Covers glslang error reporting through ShaderLibrary: broken shaders, errors inside includes and missing variant defines are named as file:line.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "glslang_compiler.h"

namespace oasis {
namespace {

// Every program variant is compiled and linked by glslang_compile_test.cpp; this file checks the
// failure paths and that their messages point at the right file and line.

using namespace glslang_test;

// 1-based line of the first line of `path` containing `needle`, or 0.
int lineContaining(const std::string& path, const std::string& needle) {
    std::ifstream in(path);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number)
        if (line.find(needle) != std::string::npos) return number;
    return 0;
}

// A temporary shader directory holding a copy of the real shaders/common/ and a few test shaders.
class BrokenShaders : public ::testing::Test {
protected:
    void SetUp() override {
        real = findShaderDirectory();
        ASSERT_FALSE(real.empty()) << "shader directory not found";
        std::string pattern = (std::filesystem::temp_directory_path() / "oasis-glslang-XXXXXX").string();
        std::vector<char> buffer(pattern.begin(), pattern.end());
        buffer.push_back('\0');
        ASSERT_NE(mkdtemp(buffer.data()), nullptr);
        root = buffer.data();
        std::filesystem::copy(real + "/common", root + "/common", std::filesystem::copy_options::recursive);
        write("plain.vert", "out vec2 vUv;\nvoid main() { vUv = vec2(0.0); gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }\n");
        // The error is on line 9, after three includes that expand to hundreds of lines.
        write("broken.frag",
              "// a shader with one mistake\n"                      // 1
              "#include \"common/frame_block.glsl\"\n"              // 2
              "#include \"common/surface.glsl\"\n"                  // 3
              "#include \"common/emit_surface.glsl\"\n"             // 4
              "in vec2 vUv;\n"                                      // 5
              "\n"                                                  // 6
              "void main() {\n"                                     // 7
              "    vec3 fine = vec3(vUv, 0.0);\n"                   // 8
              "    vec3 wrong = fine * undeclaredBrokenThing;\n"    // 9
              "}\n");
        write("common/oops.glsl", "// a helper with a mistake\nfloat oops() {\n    return notDeclaredInOops;\n}\n");
        write("uses_oops.frag",
              "#include \"common/frame_block.glsl\"\n"
              "#include \"common/oops.glsl\"\n"
              "out vec4 colour;\n"
              "void main() { colour = vec4(oops()); }\n");
        write("no_main.frag", "#include \"common/frame_block.glsl\"\nout vec4 colour;\nvoid notMain() { colour = vec4(1.0); }\n");
        write("fine.frag", "#include \"common/frame_block.glsl\"\nin vec2 vUv;\nout vec4 colour;\n"
                           "void main() { colour = vec4(vUv, frame.depthRange.x, 1.0); }\n");
    }
    void TearDown() override {
        if (!root.empty()) std::filesystem::remove_all(root);
    }
    void write(const std::string& name, const std::string& text) { std::ofstream(root + "/" + name) << text; }
    std::string real, root;
};

TEST_F(BrokenShaders, CopyOfCommonCompilesWhenNothingIsBroken) {
    // The control: the same setup without a mistake compiles and links, so the failures below
    // come from the mistakes and not from the copy.
    ShaderLibrary library(root);
    std::string log;
    EXPECT_TRUE(compileAndLink(library, "plain.vert", "fine.frag", {}, log)) << log;
}

TEST_F(BrokenShaders, ErrorIsReportedAtTheBrokenFileAndLine) {
    ShaderLibrary library(root);
    std::string log;
    ASSERT_FALSE(compileAndLink(library, "plain.vert", "broken.frag", {"OUTPUT_GBUFFER"}, log));
    EXPECT_NE(log.find("broken.frag:9"), std::string::npos) << log;
    EXPECT_NE(log.find("undeclaredBrokenThing"), std::string::npos) << log;
    // Raw "index:line" locations are gone: the broken file is source 0.
    EXPECT_EQ(log.find(" 0:9"), std::string::npos) << log;
}

TEST_F(BrokenShaders, ErrorInsideAnIncludedFileNamesThatFile) {
    ShaderLibrary library(root);
    std::string log;
    ASSERT_FALSE(compileAndLink(library, "plain.vert", "uses_oops.frag", {}, log));
    EXPECT_NE(log.find("common/oops.glsl:3"), std::string::npos) << log;
    EXPECT_NE(log.find("notDeclaredInOops"), std::string::npos) << log;
}

TEST_F(BrokenShaders, MissingMainFailsAtLink) {
    ShaderLibrary library(root);
    std::string log;
    EXPECT_FALSE(compileAndLink(library, "plain.vert", "no_main.frag", {}, log));
    EXPECT_NE(log.find("link:"), std::string::npos) << log;
}

// Variants differ only by #define; the shared files refuse to build without one. The failure is
// reported at the #error line of the real file that holds it (for terrain.frag that is
// common/emit_surface.glsl, after a branch with an #include the missing define switched off).
TEST(VariantDefines, SharedFilesRefuseToBuildWithoutTheirDefine) {
    std::string directory = findShaderDirectory();
    ASSERT_FALSE(directory.empty());
    ShaderLibrary library(directory);
    struct Case { const char* vertex; const char* fragment; const char* errorFile; };
    for (Case c : {Case{"fullscreen.vert", "floor.frag", "floor.frag"},
                   Case{"fullscreen.vert", "debug_view.frag", "debug_view.frag"},
                   Case{"terrain.vert", "terrain.frag", "common/emit_surface.glsl"}}) {
        int errorLine = lineContaining(directory + "/" + c.errorFile, "#error");
        ASSERT_GT(errorLine, 0) << c.errorFile;
        std::string log;
        EXPECT_FALSE(compileAndLink(library, c.vertex, c.fragment, {}, log)) << c.fragment;
        std::string expected = std::string(c.errorFile) + ":" + std::to_string(errorLine) + ":";
        EXPECT_NE(log.find(expected), std::string::npos) << c.fragment << ": expected " << expected << " in\n" << log;
    }
    // With a define from the variant table they build.
    for (const char* name : {"floor.write", "floor.read", "present", "terrain.gbuffer"}) {
        const ProgramVariant* variant = findProgramVariant(name);
        ASSERT_NE(variant, nullptr) << name;
        std::string log;
        EXPECT_TRUE(compileAndLink(library, variant->vertexFile, variant->fragmentFile, variant->defines, log))
            << name << ":\n" << log;
    }
}

// For every program variant: a shader whose last line is an #error must be reported at exactly
// that file:line. A copy of the real shader tree gets a probed twin of each stage file (the
// original text plus "#error" on the line after its last), so the expected line is known without
// reading any compiler output. This catches #line bookkeeping that goes wrong anywhere in the file,
// including in branches the variant's defines switch off.
class GlslangLineProbe : public ::testing::TestWithParam<std::string> {
protected:
    static void SetUpTestSuite() {
        std::string real = findShaderDirectory();
        if (real.empty()) return;
        std::string pattern = (std::filesystem::temp_directory_path() / "oasis-glslang-probe-XXXXXX").string();
        std::vector<char> buffer(pattern.begin(), pattern.end());
        buffer.push_back('\0');
        if (!mkdtemp(buffer.data())) return;
        root_ = buffer.data();
        std::filesystem::copy(real, root_, std::filesystem::copy_options::recursive);
    }
    static void TearDownTestSuite() {
        if (!root_.empty()) std::filesystem::remove_all(root_);
        root_.clear();
    }
    // Writes probe.<file> and returns the 1-based line its #error is on.
    static int writeProbe(const std::string& file, std::string& probeName) {
        std::ifstream in(root_ + "/" + file);
        std::stringstream buffer;
        buffer << in.rdbuf();
        std::string text = buffer.str();
        if (!text.empty() && text.back() != '\n') text += '\n';
        int lines = 0;
        for (char c : text) lines += c == '\n';
        probeName = "probe." + file;
        std::ofstream(root_ + "/" + probeName) << text << "#error oasis_line_probe\n";
        return lines + 1;
    }
    static std::string root_;
};
std::string GlslangLineProbe::root_;

TEST_P(GlslangLineProbe, ErrorOnTheLastLineOfEachStageIsReportedThere) {
    ASSERT_FALSE(root_.empty()) << "could not copy the shader directory";
    const ProgramVariant* variant = findProgramVariant(GetParam());
    ASSERT_NE(variant, nullptr);
    ShaderLibrary library(root_);
    struct Stage { EShLanguage language; std::string file; };
    std::vector<Stage> stages = {Stage{EShLangVertex, variant->vertexFile}, Stage{EShLangFragment, variant->fragmentFile}};
    if (variant->isCompute()) stages = {Stage{EShLangCompute, variant->computeFile}};
    for (const Stage& stage : stages) {
        std::string probe;
        int line = writeProbe(stage.file, probe);
        std::unique_ptr<glslang::TShader> shader;
        std::string log;
        EXPECT_FALSE(compileStage(library, stage.language, probe, variant->defines, shader, log))
            << variant->name << ": the probe in " << probe << " did not fire";
        std::string expected = probe + ":" + std::to_string(line) + ":";
        EXPECT_NE(log.find(expected), std::string::npos)
            << variant->name << ": expected the #error at " << expected << " but the log says:\n" << log;
    }
}

std::vector<std::string> allVariantNames() {
    std::vector<std::string> names;
    for (const ProgramVariant& variant : everyProgramVariant()) names.push_back(variant.name);
    return names;
}

std::string variantTestName(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = info.param;
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Variants, GlslangLineProbe, ::testing::ValuesIn(allVariantNames()), variantTestName);

}  // namespace
}  // namespace oasis
