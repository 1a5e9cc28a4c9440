// Compiling oasis's shaders with glslang for the tests: OpenGL semantics (no Vulkan client, no
// SPIR-V target), preprocessed by the real ShaderLibrary, logs annotated to file:line.
#pragma once
#include <glslang/Public/ShaderLang.h>

#include <memory>
#include <string>
#include <vector>

#include "debug/debug_views.h"
#include "render/shader_library.h"
#include "render/shader_variants.h"

namespace oasis::glslang_test {

// Compiles one stage; on failure `log` holds the annotated (file:line) log.
bool compileStage(const ShaderLibrary& library, EShLanguage stage, const std::string& file,
                  const std::vector<std::string>& defines, std::unique_ptr<glslang::TShader>& shader,
                  std::string& log);

// Compiles every stage of a variant (compute, or vertex + fragment) and links them.
bool compileVariant(const ShaderLibrary& library, const ProgramVariant& variant, std::string& log);

inline bool compileAndLink(const ShaderLibrary& library, const std::string& vertexFile,
                           const std::string& fragmentFile, const std::vector<std::string>& defines,
                           std::string& log) {
    return compileVariant(library, ProgramVariant{"adhoc", vertexFile, fragmentFile, defines}, log);
}

EShLanguage stageOfFile(const std::string& file);  // by extension: .vert .frag .comp

// The whole program table: the fixed programs and the debug views' (which debug/ adds).
inline const std::deque<ProgramVariant>& everyProgramVariant() {
    registerDebugViewPrograms();
    return programVariants();
}

}  // namespace oasis::glslang_test
