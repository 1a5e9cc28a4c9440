// Covers ShaderLibrary::preprocess and PreprocessedShader::annotateLog (src/render/shader_library.h) without a GL context.
#include <gtest/gtest.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "debug/debug_views.h"
#include "render/shader_library.h"
#include "render/shader_variants.h"

#include "unit_support.h"

namespace oasis {
namespace {

using namespace unittest;

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) lines.push_back(line);
    return lines;
}

size_t countOccurrences(const std::string& text, const std::string& needle) {
    size_t count = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++count;
    return count;
}

// Follows the #line directives the way a GLSL compiler does (GLSL >= 3.30: "#line N S" makes the
// next line number N of source string S) and checks every other line is the line it claims to be
// of the file files[S] on disk. Lines before the first #line are the header (version, defines).
void expectLineDirectivesMatchSources(const std::string& directory, const PreprocessedShader& shader,
                                      const std::string& what) {
    static const std::regex lineDirective(R"(^#line (\d+) (\d+)$)");
    std::map<size_t, std::vector<std::string>> sources;
    int file = -1, next = 0, checked = 0;
    for (const std::string& line : splitLines(shader.text)) {
        std::smatch match;
        if (std::regex_match(line, match, lineDirective)) {
            next = std::stoi(match[1].str());
            file = std::stoi(match[2].str());
            ASSERT_LT(size_t(file), shader.files.size()) << what << ": " << line;
            if (!sources.count(size_t(file)))
                sources[size_t(file)] = splitLines(readText(directory + "/" + shader.files[size_t(file)]));
            continue;
        }
        if (file < 0) continue;  // header
        const std::vector<std::string>& source = sources[size_t(file)];
        ASSERT_GE(next, 1) << what;
        ASSERT_LE(size_t(next), source.size()) << what << ": " << shader.files[size_t(file)] << " has no line " << next;
        ASSERT_EQ(line, source[size_t(next - 1)]) << what << ": " << shader.files[size_t(file)] << ":" << next;
        ++next;
        ++checked;
    }
    EXPECT_GT(checked, 0) << what;
}

// What a GLSL compiler's preprocessor makes of a preprocessed shader (glslang, OpenGL semantics).
bool glslPreprocess(const std::string& source, std::string& expanded, std::string& log) {
    if (!glslang::InitializeProcess()) {
        log = "glslang::InitializeProcess failed";
        return false;
    }
    bool ok = false;
    {
        glslang::TShader shader(EShLangFragment);
        const char* text = source.c_str();
        shader.setStrings(&text, 1);
        shader.setEnvInput(glslang::EShSourceGlsl, EShLangFragment, glslang::EShClientNone, 0);
        shader.setEnvClient(glslang::EShClientNone, glslang::EShTargetClientVersion(0));
        shader.setEnvTarget(glslang::EShTargetNone, glslang::EShTargetLanguageVersion(0));
        glslang::TShader::ForbidIncluder includer;
        ok = shader.preprocess(GetDefaultResources(), 450, ECoreProfile, false, false, EShMsgDefault, &expanded,
                               includer);
        log = shader.getInfoLog();
    }
    glslang::FinalizeProcess();
    return ok;
}

// A scratch shader directory, removed afterwards.
class TempShaderDir : public ::testing::Test {
protected:
    void SetUp() override {
        std::string pattern = (std::filesystem::temp_directory_path() / "oasis-preprocess-XXXXXX").string();
        std::vector<char> buffer(pattern.begin(), pattern.end());
        buffer.push_back('\0');
        ASSERT_NE(mkdtemp(buffer.data()), nullptr);
        root = buffer.data();
        std::filesystem::create_directories(root + "/common");
        write("common/a.glsl", "#ifndef A_GLSL\n#define A_GLSL\nfloat a() { return 1.0; }\n#endif\n");
        write("common/b.glsl", "// b\n#ifndef B_GLSL\n#define B_GLSL\n#include \"common/a.glsl\"\nfloat b() { return a(); }\n#endif\n");
        write("main.frag",
              "// main\n"                        // 1
              "#include \"common/a.glsl\"\n"     // 2
              "  #  include   \"common/b.glsl\"  \n"  // 3 (spaces are allowed)
              "#include \"common/a.glsl\"\n"     // 4
              "out vec4 colour;\n"               // 5
              "void main() { colour = vec4(a() + b()); }");  // 6, no final newline
        write("missing.frag", "// one\n// two\n#include \"common/nope.glsl\"\nvoid main() {}\n");
        write("common/c.glsl", "// c\n// c2\n// c3\n#include \"common/gone.glsl\"\n");
        write("nested_missing.frag", "// top\n#include \"common/c.glsl\"\nvoid main() {}\n");
        write("inactive_include.frag",
              "// an include in a branch the defines switch off\n"  // 1
              "#if defined(WITH_A)\n"                               // 2
              "#include \"common/a.glsl\"\n"                        // 3
              "#endif\n"                                            // 4
              "int probeFile = __FILE__; int probeLine = __LINE__;\n");  // 5
        write("self.frag", "// includes itself without a guard\n#include \"self.frag\"\n");
    }
    void TearDown() override {
        if (!root.empty()) std::filesystem::remove_all(root);
    }
    void write(const std::string& name, const std::string& text) { std::ofstream(root + "/" + name) << text; }
    std::string root;
};

TEST_F(TempShaderDir, VersionFirstThenExtensionsDefinesAndLineOne) {
    GlslDialect dialect;
    dialect.versionLine = "#version 330 core";
    dialect.extensionLines = {"#extension GL_ARB_shading_language_420pack : enable"};
    ShaderLibrary library(root, dialect);
    PreprocessedShader out;
    std::string error;
    ASSERT_TRUE(library.preprocess("main.frag", {"OUTPUT_GBUFFER", "LEVEL 2"}, out, error)) << error;
    std::vector<std::string> lines = splitLines(out.text);
    ASSERT_GE(lines.size(), 5u);
    EXPECT_EQ(lines[0], "#version 330 core");
    EXPECT_EQ(lines[1], "#extension GL_ARB_shading_language_420pack : enable");
    EXPECT_EQ(lines[2], "#define OUTPUT_GBUFFER");
    EXPECT_EQ(lines[3], "#define LEVEL 2");
    EXPECT_EQ(lines[4], "#line 1 0");
    EXPECT_EQ(countOccurrences(out.text, "#version"), 1u);
    EXPECT_EQ(out.text.back(), '\n');  // the last line is terminated even without a final newline
}

TEST_F(TempShaderDir, EveryIncludeIsExpandedWithItsOwnSourceIndex) {
    ShaderLibrary library(root);
    PreprocessedShader out;
    std::string error;
    ASSERT_TRUE(library.preprocess("main.frag", {}, out, error)) << error;
    // One entry per expansion, in order: main, a (line 2), b (line 3) which includes a, a (line 4).
    EXPECT_EQ(out.files, (std::vector<std::string>{"main.frag", "common/a.glsl", "common/b.glsl", "common/a.glsl",
                                                   "common/a.glsl"}));
    EXPECT_EQ(out.text.find("#include"), std::string::npos) << out.text;
    for (size_t i = 0; i < out.files.size(); ++i)
        EXPECT_EQ(countOccurrences(out.text, "#line 1 " + std::to_string(i) + "\n"), 1u) << "source " << i;
    // Back in the including file on the line after each include.
    EXPECT_NE(out.text.find("#line 3 0\n"), std::string::npos);
    EXPECT_NE(out.text.find("#line 4 0\n"), std::string::npos);
    EXPECT_NE(out.text.find("#line 5 0\n"), std::string::npos);
    EXPECT_NE(out.text.find("#line 5 2\n"), std::string::npos);  // b.glsl after its include of a
    expectLineDirectivesMatchSources(root, out, "main.frag");
}

TEST_F(TempShaderDir, GuardsLeaveOneCopyOfEachIncludeAfterGlslPreprocessing) {
    // preprocess() pastes a file at every #include; the files' #ifndef guards keep one copy. Run
    // the text through glslang's preprocessor to see what a compiler sees.
    ShaderLibrary library(root, GlslDialect{"#version 450 core", {}});
    PreprocessedShader out;
    std::string error;
    ASSERT_TRUE(library.preprocess("main.frag", {}, out, error)) << error;
    EXPECT_EQ(countOccurrences(out.text, "float a()"), 3u);  // pasted three times

    std::string expanded, log;
    ASSERT_TRUE(glslPreprocess(out.text, expanded, log)) << log;
    EXPECT_EQ(countOccurrences(expanded, "float a()"), 1u) << expanded;
    EXPECT_EQ(countOccurrences(expanded, "float b()"), 1u) << expanded;
    EXPECT_EQ(countOccurrences(expanded, "void main()"), 1u) << expanded;
}

TEST_F(TempShaderDir, RepeatedCallsStartAfresh) {
    ShaderLibrary library(root);
    PreprocessedShader out;
    std::string error;
    ASSERT_TRUE(library.preprocess("main.frag", {"X"}, out, error)) << error;
    PreprocessedShader first = out;
    ASSERT_TRUE(library.preprocess("main.frag", {"X"}, out, error)) << error;
    EXPECT_EQ(out.text, first.text);
    EXPECT_EQ(out.files, first.files);
}

TEST_F(TempShaderDir, MissingIncludeNamesTheIncludingFileAndLine) {
    ShaderLibrary library(root);
    PreprocessedShader out;
    std::string error;
    EXPECT_FALSE(library.preprocess("missing.frag", {}, out, error));
    EXPECT_NE(error.find("missing.frag:3"), std::string::npos) << error;
    EXPECT_NE(error.find("common/nope.glsl"), std::string::npos) << error;
}

TEST_F(TempShaderDir, NestedMissingIncludeNamesTheWholeChain) {
    ShaderLibrary library(root);
    PreprocessedShader out;
    std::string error;
    EXPECT_FALSE(library.preprocess("nested_missing.frag", {}, out, error));
    EXPECT_NE(error.find("nested_missing.frag:2"), std::string::npos) << error;
    EXPECT_NE(error.find("common/c.glsl:4"), std::string::npos) << error;
    EXPECT_NE(error.find("common/gone.glsl"), std::string::npos) << error;
    EXPECT_LT(error.find("nested_missing.frag:2"), error.find("common/c.glsl:4")) << "outermost first: " << error;
}

TEST_F(TempShaderDir, MissingTopLevelFileIsAnError) {
    ShaderLibrary library(root);
    PreprocessedShader out;
    std::string error;
    EXPECT_FALSE(library.preprocess("absent.vert", {}, out, error));
    EXPECT_NE(error.find("absent.vert"), std::string::npos) << error;
}

TEST_F(TempShaderDir, SelfIncludeStopsWithAnError) {
    ShaderLibrary library(root);
    PreprocessedShader out;
    std::string error;
    EXPECT_FALSE(library.preprocess("self.frag", {}, out, error));
    EXPECT_NE(error.find("nested too deeply"), std::string::npos) << error;
    EXPECT_NE(error.find("self.frag:2"), std::string::npos) << error;
}

// GLSL's __FILE__ (source string number) and __LINE__ show where the compiler thinks a line is.
// "#line" directives inside a group the preprocessor skips are ignored (GLSL spec 3.3), so the
// "#line 4 0" that preprocess() emits after an #include in an inactive #if branch never takes
// effect, and every later line of that file is numbered too high by the included text's length.
TEST_F(TempShaderDir, LineNumbersSurviveAnIncludeInAnActiveBranch) {
    ShaderLibrary library(root);
    PreprocessedShader out;
    std::string error, expanded, log;
    ASSERT_TRUE(library.preprocess("inactive_include.frag", {"WITH_A"}, out, error)) << error;
    ASSERT_TRUE(glslPreprocess(out.text, expanded, log)) << log;
    EXPECT_NE(expanded.find("probeFile = 0;"), std::string::npos) << expanded;
    EXPECT_NE(expanded.find("probeLine = 5;"), std::string::npos) << expanded;
}

TEST_F(TempShaderDir, LineNumbersSurviveAnIncludeInAnInactiveBranch) {
    ShaderLibrary library(root);
    PreprocessedShader out;
    std::string error, expanded, log;
    ASSERT_TRUE(library.preprocess("inactive_include.frag", {}, out, error)) << error;
    ASSERT_TRUE(glslPreprocess(out.text, expanded, log)) << log;
    EXPECT_NE(expanded.find("probeFile = 0;"), std::string::npos) << expanded;
    EXPECT_NE(expanded.find("probeLine = 5;"), std::string::npos)
        << "inactive_include.frag line 5 is numbered differently after preprocessing:\n" << expanded;
}

TEST(ShaderPreprocess, EveryVariantOfTheRealShadersPreprocessesWithCorrectLines) {
    std::string directory = findShaderDirectory();
    ASSERT_FALSE(directory.empty());
    ShaderLibrary library(directory);
    for (const ProgramVariant& variant : everyProgramVariant()) {
        for (const std::string& file : variant.stageFiles()) {
            PreprocessedShader out;
            std::string error;
            ASSERT_TRUE(library.preprocess(file, variant.defines, out, error)) << variant.name << ": " << error;
            EXPECT_EQ(out.text.rfind(library.dialect().versionLine + "\n", 0), 0u) << variant.name;
            for (const std::string& define : variant.defines)
                EXPECT_NE(out.text.find("\n#define " + define + "\n"), std::string::npos) << variant.name;
            EXPECT_EQ(out.files.front(), file);
            EXPECT_EQ(out.text.find("#include"), std::string::npos) << variant.name << " " << file;
            expectLineDirectivesMatchSources(directory, out, variant.name + " " + file);
        }
    }
    EXPECT_EQ(library.dialect().versionLine, "#version 450 core");  // the documented default
}

TEST(AnnotateLog, MesaAndGlslangLocationsNameTheFile) {
    PreprocessedShader shader;
    shader.files = {"main.frag", "common/a.glsl", "common/b.glsl"};
    EXPECT_EQ(shader.annotateLog("0:12(5): error: x"), "main.frag:12(5): error: x\n");
    EXPECT_EQ(shader.annotateLog("2:12(5): error: x"), "common/b.glsl:12(5): error: x\n");
    EXPECT_EQ(shader.annotateLog("ERROR: 1:7: 'y' : undeclared"), "ERROR: common/a.glsl:7: 'y' : undeclared\n");
    EXPECT_EQ(shader.annotateLog("WARNING: 0:3: 'z' : unused"), "WARNING: main.frag:3: 'z' : unused\n");
}

TEST(AnnotateLog, EachLineIndependentlyAndUnknownIndicesUntouched) {
    PreprocessedShader shader;
    shader.files = {"main.frag", "common/a.glsl"};
    std::string log =
        "ERROR: 1:7: 'y' : undeclared identifier\n"
        "ERROR: 0:20: '' : compilation terminated\n"
        "ERROR: 5:2: 'w' : index beyond the file list\n"
        "ERROR: 2 compilation errors.  No code generated.\n";
    EXPECT_EQ(shader.annotateLog(log),
              "ERROR: common/a.glsl:7: 'y' : undeclared identifier\n"
              "ERROR: main.frag:20: '' : compilation terminated\n"
              "ERROR: 5:2: 'w' : index beyond the file list\n"
              "ERROR: 2 compilation errors.  No code generated.\n");
    EXPECT_EQ(shader.annotateLog(""), "");
}

}  // namespace
}  // namespace oasis
