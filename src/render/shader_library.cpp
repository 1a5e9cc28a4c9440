// Shader loading: include resolution, variant defines, compile/link with readable errors, reload.
#include "render/shader_library.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "io/file_input.h"
#include "render/texture_units.h"

namespace oasis {
namespace {

// A shader source larger than this is not one of oasis's (the largest is a few KiB).
constexpr size_t kMaxShaderFileBytes = size_t(1) << 20;

std::string executableDirectory() {
    char path[4096];
    ssize_t length = readlink("/proc/self/exe", path, sizeof(path) - 1);
    if (length <= 0) return {};
    std::string exe(path, size_t(length));
    return exe.substr(0, exe.find_last_of('/'));
}

bool isShaderDirectory(const std::string& dir) {
    struct stat probe;  // stat, not open: a FIFO in its place must not block the search
    return stat((dir + "/common/frame_data.glsl").c_str(), &probe) == 0 && S_ISREG(probe.st_mode);
}

// Appends `file` to `out`, expanding #include "name" lines recursively.
bool expandIncludes(const std::string& root, const std::string& file, PreprocessedShader& out,
                    int depth, std::string& error) {
    if (depth > 16) { error = file + ": #include nested too deeply"; return false; }
    std::string text;
    std::string why;
    if (!readRegularFile(root + "/" + file, kMaxShaderFileBytes, text, why)) {
        error = "cannot read shader " + why.substr(std::string("cannot read ").size());  // "...: it is a directory"
        return false;
    }
    // An emptied file would surface only as a link error naming no file ("lacks main") or as
    // errors in the files that include it; say which file it is.
    if (text.find_first_not_of(" \t\r\n") == std::string::npos) { error = file + ":1: the file is empty"; return false; }
    int index = int(out.files.size());
    out.files.push_back(file);
    out.text += "#line 1 " + std::to_string(index) + "\n";
    std::istringstream lines(text);
    std::string line;
    int lineNumber = 0;
    static const std::regex includeLine(R"(^\s*#\s*include\s+\"([^\"]+)\"\s*$)");
    static const std::regex conditionalLine(R"(^\s*#\s*(if|ifdef|ifndef|elif|else|endif)\b.*)");
    while (std::getline(lines, line)) {
        ++lineNumber;
        std::smatch match;
        if (std::regex_match(line, match, includeLine)) {
            if (!expandIncludes(root, match[1].str(), out, depth + 1, error)) {
                error = file + ":" + std::to_string(lineNumber) + ": " + error;
                return false;
            }
            out.text += "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(index) + "\n";
        } else if (std::regex_match(line, conditionalLine)) {
            // A #line after an include in a branch that is switched off is skipped with the branch;
            // restating the line after every conditional keeps the numbering right regardless.
            out.text += line + "\n#line " + std::to_string(lineNumber + 1) + " " + std::to_string(index) + "\n";
        } else {
            out.text += line + "\n";
        }
    }
    return true;
}

// The light list's blocks and the water bounds (render/texture_units.h), whichever of them the
// program declares.
void bindLightBlocks(GLuint program) {
    GLuint count = glGetUniformBlockIndex(program, kLightCountBlockName);
    if (count != GL_INVALID_INDEX) glUniformBlockBinding(program, count, kLightCountBlockBinding);
    for (int k = 0;; ++k) {
        std::string name = std::string(kLightBlockName) + "[" + std::to_string(k) + "]";
        GLuint block = glGetUniformBlockIndex(program, name.c_str());
        if (block == GL_INVALID_INDEX) break;
        glUniformBlockBinding(program, block, GLuint(kLightBlockFirstBinding + k));
    }
    // OpenGL ES has no glShaderStorageBlockBinding: its storage blocks say layout(binding) themselves.
    if (!epoxy_is_desktop_gl()) return;
    if (epoxy_gl_version() < 43 && !(epoxy_has_gl_extension("GL_ARB_shader_storage_buffer_object") &&
                                     epoxy_has_gl_extension("GL_ARB_program_interface_query")))
        return;
    const std::pair<const char*, int> storage[] = {{kLightStorageName, kLightStorageBinding},
                                                   {kLightCountStorageName, kLightCountStorageBinding},
                                                   {kLightTileStorageName, kLightTileStorageBinding},
                                                   {kWaterBoundsStorageName, kWaterBoundsStorageBinding}};
    for (auto [blockName, binding] : storage) {
        GLuint index = glGetProgramResourceIndex(program, GL_SHADER_STORAGE_BLOCK, blockName);
        if (index != GL_INVALID_INDEX) glShaderStorageBlockBinding(program, index, GLuint(binding));
    }
}

// The GLSL version number of a "#version 330 core" line (450 if it cannot be read).
int glslVersionNumber(const std::string& versionLine) {
    int number = 0;
    return std::sscanf(versionLine.c_str(), "#version %d", &number) == 1 ? number : 450;
}

// The extension that gives GLSL ES 3.10 `precise` (common/turtle_transform.glsl), in the order
// gl::Capabilities::computeAvailable accepts them; "" where the context lists neither.
template <class Listed>
std::string esPreciseExtension(Listed listed) {
    for (const char* name : {"GL_EXT_gpu_shader5", "GL_OES_gpu_shader5"})
        if (listed(name)) return name;
    return {};
}

void insertAfterVersionLine(std::string& text, const std::string& lines) {
    size_t end = text.find('\n');
    text.insert(end == std::string::npos ? text.size() : end + 1, lines);
}

}  // namespace

bool GlslDialect::es() const {
    size_t end = versionLine.find_last_not_of(" \t\r\n");
    return end != std::string::npos && end >= 2 && versionLine.compare(end - 1, 2, "es") == 0;
}

GlslDialect glslDialectForEs(int major, int minor, bool clipDistances, bool depthClamp,
                             const std::string& preciseExtension, const std::string& clipDistanceDirective) {
    GlslDialect dialect;
    int version = major > 3 || (major == 3 && minor >= 2) ? 320 : (major == 3 && minor == 1 ? 310 : 300);
    dialect.versionLine = "#version " + std::to_string(version) + " es";
    if (version == 310) dialect.preciseExtension = preciseExtension;  // 320 has `precise`, 300 no compute
    if (clipDistances) dialect.extensionLines.push_back("#extension " + clipDistanceDirective + " : enable");
    else dialect.defines.push_back("OASIS_NO_CLIP_DISTANCE 1");
    if (!depthClamp) dialect.defines.push_back("OASIS_NO_DEPTH_CLAMP 1");  // passes/shadow_pass.cpp
    dialect.defines.push_back("OASIS_STORAGE_BINDINGS 1");  // common/storage_layout.glsl
    // ES fragment shaders have no default float precision and lowp samplers: every stage gets highp,
    // the precision desktop GLSL computes in, so the maths is the same.
    dialect.precisionLines = {"precision highp float;", "precision highp int;", "precision highp sampler2D;",
                              "precision highp usampler2D;", "precision highp sampler2DArrayShadow;"};
    return dialect;
}

GlslDialect glslDialectForEs(const gl::Capabilities& caps) {
    // The tier's answers (--force gles30 has neither), not the driver's own.
    return glslDialectForEs(caps.major, caps.minor, caps.clipDistancesAvailable(), caps.depthClampAvailable(),
                            esPreciseExtension([&](const char* name) { return caps.hasExtension(name); }),
                            caps.clipDistanceDirective());
}

std::string computeExtensionLines(const GlslDialect& dialect) {
    // What gl::Capabilities::computeAvailable checks for, enabled for a compute stage below GLSL 4.30:
    // compute and storage blocks, layout(binding) (420pack) and `precise` (gpu_shader5). GLSL ES
    // 3.20 has them all, 3.10 all but `precise`: EXT_ or OES_gpu_shader5 gives it there (without
    // either the capability takes the CPU path, so no compute stage is built).
    if (dialect.es())
        return dialect.preciseExtension.empty() ? "" : "#extension " + dialect.preciseExtension + " : require\n";
    int version = glslVersionNumber(dialect.versionLine);
    std::string lines;
    if (version < 430)
        lines += "#extension GL_ARB_compute_shader : require\n#extension GL_ARB_shader_storage_buffer_object : require\n";
    if (version < 420) lines += "#extension GL_ARB_shading_language_420pack : require\n";
    if (version < 400) lines += "#extension GL_ARB_gpu_shader5 : require\n";
    return lines;
}

std::string PreprocessedShader::annotateLog(const std::string& log) const {
    // Mesa writes "0:12(5): error", glslang "ERROR: 0:12: ...", NVIDIA "0(12) : error".
    static const std::regex location(R"((^|\s)(\d+)(?::(\d+)|\((\d+)\)))");
    std::string result;
    std::istringstream lines(log);
    std::string line;
    while (std::getline(lines, line)) {
        std::smatch match;
        if (std::regex_search(line, match, location)) {
            size_t index = std::stoul(match[2].str());
            std::string lineNumber = match[3].matched ? match[3].str() : match[4].str();
            if (index < files.size())
                line = match.prefix().str() + match[1].str() + files[index] + ":" + lineNumber +
                       match.suffix().str();
        }
        result += line + "\n";
    }
    return result;
}

std::string findShaderDirectory(std::string* searched) {
    // A variable that is set names the one directory the user wants: a bad one is an error, never a
    // silent fallback to another tree (that would draw with shaders the user did not choose).
    if (const char* env = std::getenv("OASIS_SHADER_DIR")) {
        std::string dir = env;
        struct stat info {};
        if (dir.empty()) throw std::runtime_error("OASIS_SHADER_DIR is set but empty; unset it or name oasis's shaders/ directory");
        if (stat(dir.c_str(), &info) != 0 || !S_ISDIR(info.st_mode))
            throw std::runtime_error("OASIS_SHADER_DIR=" + dir + " is not a directory; unset it or name oasis's shaders/ directory");
        if (!isShaderDirectory(dir))
            throw std::runtime_error("OASIS_SHADER_DIR=" + dir + " lacks the shader tree (no common/frame_data.glsl in it); "
                                     "unset it or name oasis's shaders/ directory");
        return dir;
    }
    std::vector<std::string> candidates;
    std::string exeDir = executableDirectory();
    if (!exeDir.empty()) {
        std::string installed = exeDir + "/../share/oasis/shaders";
        char resolved[4096];
        candidates.push_back(realpath(installed.c_str(), resolved) ? std::string(resolved) : installed);
    }
    candidates.push_back(OASIS_INSTALL_SHADER_DIR);
    candidates.push_back(OASIS_SOURCE_SHADER_DIR);
    std::string tried;
    for (const std::string& dir : candidates) {
        tried += (tried.empty() ? "" : ", ") + dir;
        if (isShaderDirectory(dir)) return dir;
    }
    if (searched) *searched = tried;
    return {};
}

GlslDialect glslDialectForCurrentContext() {
    if (!epoxy_is_desktop_gl())
        return glslDialectForEs(epoxy_gl_version() / 10, epoxy_gl_version() % 10,
                                epoxy_has_gl_extension("GL_EXT_clip_cull_distance") ||
                                    epoxy_has_gl_extension("GL_WEBGL_clip_cull_distance"),
                                epoxy_has_gl_extension("GL_EXT_depth_clamp"),
                                esPreciseExtension([](const char* name) { return epoxy_has_gl_extension(name); }),
                                epoxy_has_gl_extension("GL_EXT_clip_cull_distance") ? "GL_EXT_clip_cull_distance"
                                                                                     : "GL_ANGLE_clip_cull_distance");
    GlslDialect dialect;
    int version = epoxy_gl_version();  // 42 for GL 4.2; GLSL matches GL from 3.3 on
    if (version >= 33 && version < 45) dialect.versionLine = "#version " + std::to_string(version * 10) + " core";
    return dialect;
}

ShaderLibrary::ShaderLibrary(std::string directory, GlslDialect dialect)
    : directory_(std::move(directory)), dialect_(std::move(dialect)) {}

void ShaderLibrary::setContextDefines(std::vector<std::string> defines) {
    if (defines == contextDefines_) return;
    // Programs built before the first context defines use none of them (only the light programs
    // do, and the renderer sets the defines before it builds any): they stay valid.
    bool rebuild = !contextDefines_.empty();
    contextDefines_ = std::move(defines);
    if (rebuild) programs_.clear();
}

bool ShaderLibrary::preprocess(const std::string& file, const std::vector<std::string>& defines,
                               PreprocessedShader& out, std::string& error) const {
    out = {};
    out.text = dialect_.versionLine + "\n";
    for (const std::string& extension : dialect_.extensionLines) out.text += extension + "\n";
    for (const std::string& define : dialect_.defines) out.text += "#define " + define + "\n";
    for (const std::string& define : defines) out.text += "#define " + define + "\n";
    for (const std::string& define : contextDefines_) out.text += "#define " + define + "\n";
    for (const std::string& line : dialect_.precisionLines) out.text += line + "\n";
    return expandIncludes(directory_, file, out, 0, error);
}

bool ShaderLibrary::compileStage(GLenum stage, const std::string& file,
                                 const std::vector<std::string>& defines, gl::Shader& out,
                                 std::string& error) const {
    PreprocessedShader source;
    if (!preprocess(file, defines, source, error)) return false;
    if (stage == GL_COMPUTE_SHADER) insertAfterVersionLine(source.text, computeExtensionLines(dialect_));
    // The SSBO light paths below GLSL 4.30 (a 3.3 context with the extension): storage blocks.
    bool storageLights = std::any_of(defines.begin(), defines.end(), [](const std::string& define) {
        return define == "LIGHTS_SSBO" || define == "LIGHTS_SSBO_COUNT" || define == "LIGHTS_TILED";
    });
    if (storageLights && !dialect_.es() && glslVersionNumber(dialect_.versionLine) < 430)
        insertAfterVersionLine(source.text, "#extension GL_ARB_shader_storage_buffer_object : require\n");
    gl::Shader shader(glCreateShader(stage));
    gl::setLabel(shader, file);  // build() names it with its program's variant once compiled
    const char* text = source.text.c_str();
    glShaderSource(shader.name(), 1, &text, nullptr);
    glCompileShader(shader.name());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.name(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[8192] = {};
        glGetShaderInfoLog(shader.name(), sizeof(log), nullptr, log);
        error = "compiling " + file + ":\n" + source.annotateLog(log);
        return false;
    }
    out = std::move(shader);
    return true;
}

bool ShaderLibrary::build(const ProgramVariant& variant, gl::Program& out, std::string& error) const {
    const std::vector<std::string> files = variant.stageFiles();
    const GLenum graphicsStages[] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
    std::vector<gl::Shader> shaders(files.size());
    for (size_t i = 0; i < files.size(); ++i) {
        GLenum stage = variant.isCompute() ? GLenum(GL_COMPUTE_SHADER) : graphicsStages[i];
        if (!compileStage(stage, files[i], variant.defines, shaders[i], error)) {
            error = "program " + variant.name + ": " + error;
            return false;
        }
        gl::setLabel(shaders[i], variant.name + ": " + files[i]);
    }
    gl::Program program(glCreateProgram());
    gl::setLabel(program, variant.name);  // the variant table's name: "lighting.compact", "terrain.forward"
    for (const gl::Shader& shader : shaders) glAttachShader(program.name(), shader.name());
    if (!variant.feedbackVaryings.empty()) {
        std::vector<const char*> varyings;
        for (const std::string& varying : variant.feedbackVaryings) varyings.push_back(varying.c_str());
        glTransformFeedbackVaryings(program.name(), GLsizei(varyings.size()), varyings.data(), GL_INTERLEAVED_ATTRIBS);
    }
    glLinkProgram(program.name());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.name(), GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[8192] = {};
        glGetProgramInfoLog(program.name(), sizeof(log), nullptr, log);
        std::string stages;
        for (const std::string& file : files) stages += (stages.empty() ? "" : " + ") + file;
        error = "linking program " + variant.name + " (" + stages + "):\n" + log;
        return false;
    }
    for (const gl::Shader& shader : shaders) glDetachShader(program.name(), shader.name());
    // Bindings come from texture_units.h rather than layout(binding) so GLSL 3.30 works too.
    GLuint block = glGetUniformBlockIndex(program.name(), kFrameBlockName);
    if (block != GL_INVALID_INDEX) glUniformBlockBinding(program.name(), block, kFrameBlockBinding);
    bindLightBlocks(program.name());
    glUseProgram(program.name());
    for (const SamplerBinding& binding : kSamplerBindings) {
        GLint location = glGetUniformLocation(program.name(), binding.uniformName);
        if (location >= 0) glUniform1i(location, binding.unit);
    }
    glUseProgram(0);
    out = std::move(program);
    return true;
}

GLuint ShaderLibrary::program(const std::string& variantName) {
    auto found = programs_.find(variantName);
    if (found != programs_.end()) return found->second.name();
    const ProgramVariant* variant = findProgramVariant(variantName);
    if (!variant) throw std::logic_error("no shader program variant named '" + variantName + "'");
    gl::Program program;
    std::string error;
    if (!build(*variant, program, error)) throw ShaderBuildError(error);
    GLuint name = program.name();
    programs_.emplace(variantName, std::move(program));
    return name;
}

std::vector<std::string> ShaderLibrary::reloadAll() {
    std::vector<std::string> failures;
    for (auto& [name, program] : programs_) {
        gl::Program rebuilt;
        std::string error;
        if (build(*findProgramVariant(name), rebuilt, error))
            program = std::move(rebuilt);
        else
            failures.push_back(error + (error.back() == '\n' ? "" : " ") + "(keeping the previous version of " + name + ")");
    }
    return failures;
}

}  // namespace oasis
