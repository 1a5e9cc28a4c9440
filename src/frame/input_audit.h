// The frame's validation of what a pass reads (frame/frame_graph.h's audits hold what it draws
// into): a pass that samples a frame target, or reads a buffer of the frame, that it does not
// declare fails the validated frame, as one that draws into an undeclared target does.
#pragma once
#include <string>
#include <vector>

#include "passes/pass.h"

namespace oasis {

// Around one validated pass (runValidated). Before it, the units and bindings of
// render/texture_units.h's kInputBindings lose what the pass does not declare: frame targets it
// does not sample are unbound from every texture unit, buffers it does not touch from their
// bindings (kept, to be bound back after it). Whatever the pass then finds there it bound itself.
class InputAudit {
public:
    InputAudit(const Pass& pass, const PassContext& context);
    ~InputAudit();  // binds back what it took away, also when the pass threw
    InputAudit(const InputAudit&) = delete;
    InputAudit& operator=(const InputAudit&) = delete;
    // After the pass: each undeclared frame target bound on a texture unit and each undeclared
    // buffer bound where the table reads it, named with the pass; "" when nothing.
    std::string undeclaredReads() const;

private:
    struct Taken {
        GLenum target;  // GL_TEXTURE_2D_ARRAY, GL_UNIFORM_BUFFER or GL_SHADER_STORAGE_BUFFER
        GLuint binding;
        GLint name;
        GLint64 start, size;
        Resource resource;
    };
    bool samples(const Resource& target) const;
    bool touches(const Resource& resource) const;

    const Pass& pass_;
    const PassContext& context_;
    std::vector<Access> declared_;
    std::vector<Taken> taken_;
};

}  // namespace oasis
