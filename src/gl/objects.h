// Owning wrappers for OpenGL object names. Each wrapper deletes its name on destruction and
// counts itself, so tests can check that pipeline switches and resizes leak nothing; every one is
// made with a name (a KHR_debug label) that RenderDoc, apitrace and debug messages show.
#pragma once
#include <epoxy/gl.h>

#include <string>
#include <utility>

namespace oasis::gl {

enum class ObjectKind { Buffer, Texture, Framebuffer, VertexArray, Program, Shader, Sampler, Query, Count };

// Live objects created through these wrappers, by kind.
int liveObjectCount(ObjectKind kind);
int liveObjectCount();

// One owned GL name. Move-only.
template <ObjectKind Kind>
class Object {
public:
    Object() = default;
    explicit Object(GLuint name) : name_(name) { if (name_) track(+1); }
    ~Object() { reset(); }
    Object(Object&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    Object& operator=(Object&& other) noexcept {
        if (this != &other) { reset(); name_ = std::exchange(other.name_, 0); }
        return *this;
    }
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;

    GLuint name() const { return name_; }
    explicit operator bool() const { return name_ != 0; }
    void reset();

private:
    static void track(int delta);
    GLuint name_ = 0;
};

using Buffer = Object<ObjectKind::Buffer>;
using Texture = Object<ObjectKind::Texture>;
using Framebuffer = Object<ObjectKind::Framebuffer>;
using VertexArray = Object<ObjectKind::VertexArray>;
using Program = Object<ObjectKind::Program>;
using Shader = Object<ObjectKind::Shader>;
using Sampler = Object<ObjectKind::Sampler>;
using Query = Object<ObjectKind::Query>;

// Each is created and named at once: `label` is what capture tools list it as ("G-buffer albedo
// (compact)", "point lights"). Labels need KHR_debug (GL 4.3); without it they are skipped.
Buffer createBuffer(const std::string& label);
Framebuffer createFramebuffer(const std::string& label);
VertexArray createVertexArray(const std::string& label);
Sampler createSampler(const std::string& label);
// A query object of `target` (GL_ANY_SAMPLES_PASSED, ...): begun once here so that it exists and
// takes its label, and so an early glBeginConditionalRender on it reads "samples passed".
Query createQuery(GLenum target, const std::string& label);

// A texture for a render target: immutable storage, nearest filtering (of level 0), clamped.
// `levels` > 1 leaves room for a mipmap chain that a sampler object may read.
Texture createTargetTexture(const std::string& label, GLenum internalFormat, int width, int height, int levels = 1);

// (Re)names an existing object (one already bound once, or a program or shader). Labels longer
// than the driver's GL_MAX_LABEL_LENGTH are cut to it.
void setLabel(ObjectKind kind, GLuint name, const std::string& label);
template <ObjectKind Kind>
void setLabel(const Object<Kind>& object, const std::string& label) { setLabel(Kind, object.name(), label); }
// What setLabel gave the object ("" without KHR_debug or a label): for tests and messages.
std::string objectLabel(ObjectKind kind, GLuint name);
bool hasObjectLabels();

// Opens a KHR_debug group for the lifetime of the scope, when the context has KHR_debug.
class DebugGroup {
public:
    explicit DebugGroup(const char* name);
    ~DebugGroup();
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
private:
    bool open_ = false;
};

bool hasDebugGroups();
// The names of the debug groups open now, outermost first ("LightingPass / DebugViewPass"): what
// --gl-debug prints with an error. Kept by DebugGroup, so it holds only oasis's own groups.
std::string debugGroupPath();
std::string errorString(GLenum error);

// Copies `size` bytes from the start of the buffer bound to `target` into `out`: glGetBufferSubData
// on desktop GL; OpenGL ES has none, so there through glMapBufferRange (read-only).
void readBufferData(GLenum target, GLsizeiptr size, void* out);

}  // namespace oasis::gl
