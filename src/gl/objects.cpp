// GL object wrappers, live counts and debug groups.
#include "gl/objects.h"

#include <array>

namespace oasis::gl {
namespace {
std::array<int, size_t(ObjectKind::Count)> gLiveObjects{};
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

Buffer createBuffer() { GLuint n = 0; glGenBuffers(1, &n); return Buffer(n); }
Texture createTexture() { GLuint n = 0; glGenTextures(1, &n); return Texture(n); }
Framebuffer createFramebuffer() { GLuint n = 0; glGenFramebuffers(1, &n); return Framebuffer(n); }
VertexArray createVertexArray() { GLuint n = 0; glGenVertexArrays(1, &n); return VertexArray(n); }
Sampler createSampler() { GLuint n = 0; glGenSamplers(1, &n); return Sampler(n); }

Texture createTargetTexture(GLenum internalFormat, int width, int height, int levels) {
    Texture texture = createTexture();
    glBindTexture(GL_TEXTURE_2D, texture.name());
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
    open_ = true;
}

DebugGroup::~DebugGroup() {
    if (open_) glPopDebugGroup();
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

}  // namespace oasis::gl
