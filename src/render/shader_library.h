// Loads GLSL from shaders/: resolves #include "..." (with #line so errors name file:line),
// prepends the version header and the variant's #defines, compiles and links, caches by variant
// name, and reloads on request keeping the last good program when an edit fails to compile.
#pragma once
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl/capabilities.h"
#include "gl/objects.h"
#include "render/shader_variants.h"

namespace oasis {

// A shader after preprocessing: the text and the files its #line numbers refer to.
struct PreprocessedShader {
    std::string text;
    std::vector<std::string> files;  // index used in "#line N index"
    // Rewrites "index:line" in a compiler log to "file:line".
    std::string annotateLog(const std::string& log) const;
};

// The directory holding the shaders: $OASIS_SHADER_DIR, the installed share dir next to the
// executable, or the source tree this binary was built from. Empty if none has them. Throws
// std::runtime_error naming the variable when OASIS_SHADER_DIR is set but empty, not a directory
// or without the shader tree (the commands exit 1).
std::string findShaderDirectory(std::string* searched = nullptr);

// Text for `#version`: the GLSL the context speaks (450 core by default). An OpenGL ES dialect
// ("#version 320 es" / "300 es") adds default precisions after the defines and, where the context
// lacks gl_ClipDistance, OASIS_NO_CLIP_DISTANCE (common/water_clip.glsl clips by discard instead).
struct GlslDialect {
    std::string versionLine = "#version 450 core";
    std::vector<std::string> extensionLines;
    std::vector<std::string> defines;         // the dialect's own, before the variant's
    std::vector<std::string> precisionLines;  // ES: "precision highp float;" and the samplers'
    std::string preciseExtension;             // ES 3.1: the gpu_shader5 extension compute stages enable
    bool es() const;                          // the version line ends in "es"
};

// The current context's own GLSL when it is older than 4.50 ("#version 420 core" on a GL 4.2
// context, e.g. llvmpipe without compute shaders), so the same shaders run there; 450 otherwise.
GlslDialect glslDialectForCurrentContext();

// The OpenGL ES dialect of an ES context: "#version 320 es" on ES 3.2 (310 on 3.1, 300 on 3.0 and
// under --force gles30), highp defaults for float, int and the samplers oasis uses, and
// GL_EXT_clip_cull_distance where the context has it (else OASIS_NO_CLIP_DISTANCE), and
// OASIS_NO_DEPTH_CLAMP where it lacks GL_EXT_depth_clamp (the shadow casters' fallback). On ES 3.1
// compute stages enable GL_EXT_gpu_shader5 (else GL_OES_gpu_shader5) where listed, for `precise`.
GlslDialect glslDialectForEs(const gl::Capabilities& caps);
// The same from an ES version, whether gl_ClipDistance and GL_DEPTH_CLAMP exist and which
// gpu_shader5 extension ES 3.1 has ("" none; the shader tests' ES variants); `clipDistanceDirective`
// is the extension that brings gl_ClipDistance (WebGL 2's is GL_ANGLE_clip_cull_distance).
GlslDialect glslDialectForEs(int major, int minor, bool clipDistances, bool depthClamp,
                             const std::string& preciseExtension = {},
                             const std::string& clipDistanceDirective = "GL_EXT_clip_cull_distance");

// The #extension lines a compute stage needs in this dialect (none at GLSL 4.30 and later).
std::string computeExtensionLines(const GlslDialect& dialect);

// A program that does not compile or link (or whose files are missing or empty): the message
// names the program and file:line. Recoverable: the library is unchanged, so a caller that asked
// for a new configuration can go back to one whose programs are built.
class ShaderBuildError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class ShaderLibrary {
public:
    explicit ShaderLibrary(std::string directory, GlslDialect dialect = {});

    const std::string& directory() const { return directory_; }
    const GlslDialect& dialect() const { return dialect_; }
    // Defines whose values the context decides (e.g. "LIGHTS_UBO_CAPACITY 2048"), added after every
    // variant's own; changing them drops the built programs so the next request rebuilds them.
    void setContextDefines(std::vector<std::string> defines);
    const std::vector<std::string>& contextDefines() const { return contextDefines_; }

    // Preprocesses one stage of a variant; returns false with a message on a missing file.
    bool preprocess(const std::string& file, const std::vector<std::string>& defines,
                    PreprocessedShader& out, std::string& error) const;

    // The linked program for a variant from the table, built on first use. Throws ShaderBuildError
    // naming file:line when it does not build (nothing is cached then: the next request tries
    // again), std::logic_error for a name the table lacks.
    GLuint program(const std::string& variantName);

    // Rebuilds every cached program from disk. A variant that fails keeps its previous program;
    // the returned messages say which and why (empty when all succeeded).
    std::vector<std::string> reloadAll();
    // How many programs are built (what reloadAll rebuilds).
    size_t programCount() const { return programs_.size(); }

private:
    bool build(const ProgramVariant& variant, gl::Program& out, std::string& error) const;
    bool compileStage(GLenum stage, const std::string& file, const std::vector<std::string>& defines,
                      gl::Shader& out, std::string& error) const;

    std::string directory_;
    GlslDialect dialect_;
    std::vector<std::string> contextDefines_;
    std::map<std::string, gl::Program> programs_;
};

}  // namespace oasis
