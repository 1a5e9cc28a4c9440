// Every shader program variant oasis can request, compiled and linked by glslang with OpenGL
// semantics (no GL context): a variant that does not compile fails here naming file:line.
#include <gtest/gtest.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <unistd.h>

#include "render/shader_library.h"
#include "render/shader_variants.h"

namespace oasis {
namespace {

class GlslangProcess : public ::testing::Environment {
public:
    void SetUp() override { glslang::InitializeProcess(); }
    void TearDown() override { glslang::FinalizeProcess(); }
};
const auto* const kGlslang = ::testing::AddGlobalTestEnvironment(new GlslangProcess);

// Compiles one stage; on failure returns false and the log with file:line names.
bool compileStage(glslang::TProgram& program, std::vector<std::unique_ptr<glslang::TShader>>& keep,
                  const ShaderLibrary& library, EShLanguage stage, const std::string& file,
                  const std::vector<std::string>& defines, std::string& log) {
    PreprocessedShader source;
    std::string error;
    if (!library.preprocess(file, defines, source, error)) { log = error; return false; }
    auto shader = std::make_unique<glslang::TShader>(stage);
    const char* text = source.text.c_str();
    shader->setStrings(&text, 1);
    // OpenGL semantics: no Vulkan/SPIR-V client or target, so plain uniforms and gl_VertexID work.
    shader->setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientNone, 0);
    shader->setEnvClient(glslang::EShClientNone, glslang::EShTargetClientVersion(0));
    shader->setEnvTarget(glslang::EShTargetNone, glslang::EShTargetLanguageVersion(0));
    if (!shader->parse(GetDefaultResources(), 450, ECoreProfile, false, false, EShMsgDefault)) {
        log = file + ":\n" + source.annotateLog(shader->getInfoLog());
        return false;
    }
    program.addShader(shader.get());
    keep.push_back(std::move(shader));
    return true;
}

// The glslang stage of each file a variant names: one compute stage, or vertex and fragment.
std::vector<std::pair<EShLanguage, std::string>> variantStages(const ProgramVariant& variant) {
    if (variant.isCompute()) return {{EShLangCompute, variant.computeFile}};
    return {{EShLangVertex, variant.vertexFile}, {EShLangFragment, variant.fragmentFile}};
}

bool compileVariant(const ShaderLibrary& library, const ProgramVariant& variant, std::string& log) {
    glslang::TProgram program;
    std::vector<std::unique_ptr<glslang::TShader>> shaders;
    for (const auto& [stage, file] : variantStages(variant))
        if (!compileStage(program, shaders, library, stage, file, variant.defines, log)) return false;
    if (!program.link(EShMsgDefault)) {
        log = std::string("link: ") + program.getInfoLog();
        return false;
    }
    return true;
}

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

TEST(ShaderVariants, TableCoversEveryShaderFile) {
    // Every .vert/.frag/.comp in shaders/ is used by some variant: no shader escapes compilation.
    std::set<std::string> used;
    for (const ProgramVariant& variant : programVariants())
        for (const auto& [stage, file] : variantStages(variant)) used.insert(file);
    for (const auto& entry : std::filesystem::directory_iterator(findShaderDirectory())) {
        std::string ext = entry.path().extension().string();
        if (ext == ".vert" || ext == ".frag" || ext == ".comp")
            EXPECT_TRUE(used.count(entry.path().filename().string())) << entry.path() << " is in no variant";
    }
}

TEST(ShaderErrors, BrokenShaderIsReportedAtItsFileAndLine) {
    // A copy of the shader tree plus a fragment shader with an error on its line 4 (an include
    // comes first, so the line numbering must survive include expansion).
    namespace fs = std::filesystem;
    fs::path root = fs::temp_directory_path() / ("oasis-glslang-" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::copy(findShaderDirectory(), root, fs::copy_options::recursive);
    std::ofstream(root / "broken.frag") << "// a broken shader\n"
                                           "#include \"common/frame_block.glsl\"\n"
                                           "out vec4 colour;\n"
                                           "void main() { colour = vec4(undeclaredThing); }\n";
    ShaderLibrary library(root.string());
    ProgramVariant broken{"broken", "fullscreen.vert", "broken.frag", {}};
    std::string log;
    EXPECT_FALSE(compileVariant(library, broken, log));
    EXPECT_NE(log.find("broken.frag:4"), std::string::npos) << log;
    EXPECT_NE(log.find("undeclaredThing"), std::string::npos) << log;
    fs::remove_all(root);
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
