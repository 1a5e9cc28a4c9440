// GL object wrappers, live counts and debug groups.
#include "gl/objects.h"

#include <cstring>
#include <stdexcept>

#include <algorithm>
#include <array>
#include <vector>

namespace oasis::gl {
namespace {
std::array<int, size_t(ObjectKind::Count)> gLiveObjects{};
std::vector<std::string> gOpenGroups;  // DebugGroup's names, outermost first (copies: callers pass temporaries)

GLenum labelIdentifier(ObjectKind kind) {
    switch (kind) {
        case ObjectKind::Buffer: return GL_BUFFER;
        case ObjectKind::Texture: return GL_TEXTURE;
        case ObjectKind::Framebuffer: return GL_FRAMEBUFFER;
        case ObjectKind::VertexArray: return GL_VERTEX_ARRAY;
        case ObjectKind::Program: return GL_PROGRAM;
        case ObjectKind::Shader: return GL_SHADER;
        case ObjectKind::Sampler: return GL_SAMPLER;
        case ObjectKind::Query: return GL_QUERY;
        case ObjectKind::Count: break;
    }
    return GL_NONE;
}

// glGen* hands out names that become objects only when first bound, and glObjectLabel needs an
// object: each create binds its new name once and puts the previous binding back, so creating
// never changes what is bound.
template <typename Bind>
void bindOnce(GLenum bindingQuery, GLuint name, Bind bind) {
    GLint previous = 0;
    glGetIntegerv(bindingQuery, &previous);
    bind(name);
    bind(GLuint(previous));
}
}  // namespace

bool hasObjectLabels() { return hasDebugGroups(); }

void setLabel(ObjectKind kind, GLuint name, const std::string& label) {
    if (!name || !hasObjectLabels()) return;
    GLint maxLength = 0;
    glGetIntegerv(GL_MAX_LABEL_LENGTH, &maxLength);
    GLsizei length = GLsizei(std::min<size_t>(label.size(), size_t(std::max(maxLength - 1, 0))));
    glObjectLabel(labelIdentifier(kind), name, length, label.c_str());
}

std::string objectLabel(ObjectKind kind, GLuint name) {
    if (!name || !hasObjectLabels()) return {};
    char text[256] = {};
    GLsizei length = 0;
    glGetObjectLabel(labelIdentifier(kind), name, sizeof(text), &length, text);
    return std::string(text, size_t(std::max(length, 0)));
}

int liveObjectCount(ObjectKind kind) { return gLiveObjects[size_t(kind)]; }
int liveObjectCount() {
    int total = 0;
    for (int count : gLiveObjects) total += count;
    return total;
}

template <ObjectKind Kind>
void Object<Kind>::track(int delta) { gLiveObjects[size_t(Kind)] += delta; }

template <ObjectKind Kind>
void Object<Kind>::reset() {
    if (!name_) return;
    switch (Kind) {
        case ObjectKind::Buffer: glDeleteBuffers(1, &name_); break;
        case ObjectKind::Texture: glDeleteTextures(1, &name_); break;
        case ObjectKind::Framebuffer: glDeleteFramebuffers(1, &name_); break;
        case ObjectKind::VertexArray: glDeleteVertexArrays(1, &name_); break;
        case ObjectKind::Program: glDeleteProgram(name_); break;
        case ObjectKind::Shader: glDeleteShader(name_); break;
        case ObjectKind::Sampler: glDeleteSamplers(1, &name_); break;
        case ObjectKind::Query: glDeleteQueries(1, &name_); break;
        case ObjectKind::Count: break;
    }
    track(-1);
    name_ = 0;
}

template class Object<ObjectKind::Buffer>;
template class Object<ObjectKind::Texture>;
template class Object<ObjectKind::Framebuffer>;
template class Object<ObjectKind::VertexArray>;
template class Object<ObjectKind::Program>;
template class Object<ObjectKind::Shader>;
template class Object<ObjectKind::Sampler>;
template class Object<ObjectKind::Query>;

Buffer createBuffer(const std::string& label) {
    GLuint n = 0;
    glGenBuffers(1, &n);
    if (hasObjectLabels()) {
        bindOnce(GL_COPY_WRITE_BUFFER_BINDING, n, [](GLuint b) { glBindBuffer(GL_COPY_WRITE_BUFFER, b); });
        setLabel(ObjectKind::Buffer, n, label);
    }
    return Buffer(n);
}

Framebuffer createFramebuffer(const std::string& label) {
    GLuint n = 0;
    glGenFramebuffers(1, &n);
    if (hasObjectLabels()) {
        bindOnce(GL_DRAW_FRAMEBUFFER_BINDING, n, [](GLuint f) { glBindFramebuffer(GL_DRAW_FRAMEBUFFER, f); });
        setLabel(ObjectKind::Framebuffer, n, label);
    }
    return Framebuffer(n);
}

VertexArray createVertexArray(const std::string& label) {
    GLuint n = 0;
    glGenVertexArrays(1, &n);
    if (hasObjectLabels()) {
        bindOnce(GL_VERTEX_ARRAY_BINDING, n, [](GLuint v) { glBindVertexArray(v); });
        setLabel(ObjectKind::VertexArray, n, label);
    }
    return VertexArray(n);
}

Sampler createSampler(const std::string& label) {
    GLuint n = 0;
    glGenSamplers(1, &n);
    // Mesa makes the object at glGenSamplers; NVIDIA's driver only at the first bind (its
    // glObjectLabel refused the unbound name with GL_INVALID_VALUE): bound once, like the rest.
    if (hasObjectLabels()) {
        bindOnce(GL_SAMPLER_BINDING, n, [](GLuint s) {
            GLint unit = GL_TEXTURE0;
            glGetIntegerv(GL_ACTIVE_TEXTURE, &unit);
            glBindSampler(GLuint(unit - GL_TEXTURE0), s);
        });
        setLabel(ObjectKind::Sampler, n, label);
    }
    return Sampler(n);
}

Query createQuery(GLenum target, const std::string& label) {
    GLuint n = 0;
    glGenQueries(1, &n);
    glBeginQuery(target, n);  // a query is an object from its first glBeginQuery on
    glEndQuery(target);
    setLabel(ObjectKind::Query, n, label);
    return Query(n);
}

Texture createTargetTexture(const std::string& label, GLenum internalFormat, int width, int height, int levels) {
    GLuint n = 0;
    glGenTextures(1, &n);
    Texture texture(n);
    glBindTexture(GL_TEXTURE_2D, texture.name());
    setLabel(texture, label);
    glTexStorage2D(GL_TEXTURE_2D, levels, internalFormat, width, height);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

bool hasDebugGroups() {
    return epoxy_gl_version() >= 43 || epoxy_has_gl_extension("GL_KHR_debug");
}

DebugGroup::DebugGroup(const char* name) {
    if (!hasDebugGroups()) return;
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name);
    gOpenGroups.push_back(name);
    open_ = true;
}

DebugGroup::~DebugGroup() {
    if (!open_) return;
    glPopDebugGroup();
    gOpenGroups.pop_back();
}

std::string debugGroupPath() {
    std::string path;
    for (const std::string& name : gOpenGroups) path += (path.empty() ? "" : " / ") + name;
    return path.empty() ? "(no debug group)" : path;
}

std::string errorString(GLenum error) {
    switch (error) {
        case GL_NO_ERROR: return "GL_NO_ERROR";
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
        default: return "GL error " + std::to_string(error);
    }
}

void readBufferData(GLenum target, GLsizeiptr size, void* out) {
    if (size <= 0) return;
#ifdef __EMSCRIPTEN__
    glGetBufferSubData(target, 0, size, out);  // WebGL 2 reads buffers so; it cannot map them for reading
    return;
#endif
    if (epoxy_is_desktop_gl()) {
        glGetBufferSubData(target, 0, size, out);
        return;
    }
    const void* mapped = glMapBufferRange(target, 0, size, GL_MAP_READ_BIT);
    if (!mapped) throw std::runtime_error("cannot map a buffer to read it back (glMapBufferRange failed)");
    std::memcpy(out, mapped, size_t(size));
    glUnmapBuffer(target);
}

}  // namespace oasis::gl
