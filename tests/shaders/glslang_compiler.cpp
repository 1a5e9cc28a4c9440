// glslang set-up for the shader tests: the process-wide initialisation and the compile helpers.
#include "glslang_compiler.h"

#include <gtest/gtest.h>
#include <glslang/Public/ResourceLimits.h>

namespace oasis::glslang_test {
namespace {

class GlslangProcess : public ::testing::Environment {
public:
    void SetUp() override { ASSERT_TRUE(glslang::InitializeProcess()); }
    void TearDown() override { glslang::FinalizeProcess(); }
};
const auto* const kGlslangProcess = ::testing::AddGlobalTestEnvironment(new GlslangProcess);

}  // namespace

EShLanguage stageOfFile(const std::string& file) {
    auto endsWith = [&](const char* suffix) {
        std::string s(suffix);
        return file.size() >= s.size() && file.compare(file.size() - s.size(), s.size(), s) == 0;
    };
    if (endsWith(".comp")) return EShLangCompute;
    if (endsWith(".vert")) return EShLangVertex;
    return EShLangFragment;
}

bool compileStage(const ShaderLibrary& library, EShLanguage stage, const std::string& file,
                  const std::vector<std::string>& defines, std::unique_ptr<glslang::TShader>& shader,
                  std::string& log) {
    PreprocessedShader source;
    std::string error;
    if (!library.preprocess(file, defines, source, error)) {
        log = error;
        return false;
    }
    // A compute stage's #extension lines, after the version line as ShaderLibrary::compileStage puts them.
    if (stage == EShLangCompute) {
        size_t end = source.text.find('\n');
        source.text.insert(end == std::string::npos ? source.text.size() : end + 1, computeExtensionLines(library.dialect()));
    }
    shader = std::make_unique<glslang::TShader>(stage);
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
    return true;
}

bool compileVariant(const ShaderLibrary& library, const ProgramVariant& variant, std::string& log) {
    glslang::TProgram program;
    std::vector<std::unique_ptr<glslang::TShader>> shaders;
    for (const std::string& file : variant.stageFiles()) {
        std::unique_ptr<glslang::TShader> shader;
        if (!compileStage(library, stageOfFile(file), file, variant.defines, shader, log)) return false;
        program.addShader(shader.get());
        shaders.push_back(std::move(shader));
    }
    if (!program.link(EShMsgDefault)) {
        log = std::string("link: ") + program.getInfoLog();
        return false;
    }
    return true;
}

}  // namespace oasis::glslang_test
