// The validation of a pass's reads (frame/input_audit.h) over render/texture_units.h's table.
#include "frame/input_audit.h"

#include <algorithm>

#include "frame/frame_graph.h"
#include "render/texture_units.h"

namespace oasis {
namespace {

// Where storage blocks exist (desktop 4.3 or its extension, ES 3.1): elsewhere their bindings
// cannot be asked about, and no program reads them.
bool storageBindingsExist() {
    if (!epoxy_is_desktop_gl()) return epoxy_gl_version() >= 31;
    return epoxy_gl_version() >= 43 || epoxy_has_gl_extension("GL_ARB_shader_storage_buffer_object");
}

// The buffer bindings of the table's rows: each block row's binding, the light list's block
// array from its first binding up to the context's last (LightBlock[k] at kLightBlockFirstBinding + k).
struct BufferSlot {
    GLenum target;
    GLuint binding;
    Resource resource;
};
std::vector<BufferSlot> bufferSlots() {
    std::vector<BufferSlot> slots;
    bool storage = storageBindingsExist();
    GLint uniformBindings = 0;
    glGetIntegerv(GL_MAX_UNIFORM_BUFFER_BINDINGS, &uniformBindings);
    for (const InputBinding& row : kInputBindings) {
        if (row.slot == InputSlot::StorageBlock && storage)
            slots.push_back({GL_SHADER_STORAGE_BUFFER, GLuint(row.binding), row.resource});
        if (row.slot != InputSlot::UniformBlock) continue;
        int last = row.binding == kLightBlockFirstBinding ? uniformBindings - 1 : row.binding;
        for (int binding = row.binding; binding <= last; ++binding)
            slots.push_back({GL_UNIFORM_BUFFER, GLuint(binding), row.resource});
    }
    return slots;
}

GLint boundTexture(GLenum kind, int unit) {
    GLint texture = 0;
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glGetIntegerv(kind == GL_TEXTURE_2D ? GL_TEXTURE_BINDING_2D : GL_TEXTURE_BINDING_2D_ARRAY, &texture);
    return texture;
}

GLint boundBuffer(GLenum target, GLuint binding) {
    GLint name = 0;
    glGetIntegeri_v(target == GL_UNIFORM_BUFFER ? GL_UNIFORM_BUFFER_BINDING : GL_SHADER_STORAGE_BUFFER_BINDING,
                    binding, &name);
    return name;
}

const char* slotName(GLenum target) {
    switch (target) {
        case GL_UNIFORM_BUFFER: return "uniform block binding";
        case GL_SHADER_STORAGE_BUFFER: return "storage block binding";
        default: return "texture unit";
    }
}

}  // namespace

InputAudit::InputAudit(const Pass& pass, const PassContext& context)
    : pass_(pass), context_(context), declared_(pass.accesses(context.frame)) {
    GLint active = GL_TEXTURE0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    // Frame targets the pass does not sample, left on any unit by an earlier pass or a view.
    for (int unit = 0; unit < kTextureUnitCount; ++unit) {
        std::vector<Resource> held = targetsHolding(context_.targets, boundTexture(GL_TEXTURE_2D, unit));
        if (!held.empty() && std::none_of(held.begin(), held.end(), [&](const Resource& t) { return samples(t); }))
            glBindTexture(GL_TEXTURE_2D, 0);
    }
    // The shadow maps and buffers bound for the whole frame, where the pass does not touch them.
    for (const InputBinding& row : kInputBindings) {
        if (row.slot != InputSlot::TextureArray || touches(row.resource)) continue;
        GLint texture = boundTexture(GL_TEXTURE_2D_ARRAY, row.binding);
        if (texture == 0) continue;
        taken_.push_back({GL_TEXTURE_2D_ARRAY, GLuint(row.binding), texture, 0, 0, row.resource});
        glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    }
    glActiveTexture(GLenum(active));
    for (const BufferSlot& slot : bufferSlots()) {
        if (touches(slot.resource)) continue;
        GLint name = boundBuffer(slot.target, slot.binding);
        if (name == 0) continue;
        bool uniform = slot.target == GL_UNIFORM_BUFFER;
        GLint64 start = 0, size = 0;
        glGetInteger64i_v(uniform ? GL_UNIFORM_BUFFER_START : GL_SHADER_STORAGE_BUFFER_START, slot.binding, &start);
        glGetInteger64i_v(uniform ? GL_UNIFORM_BUFFER_SIZE : GL_SHADER_STORAGE_BUFFER_SIZE, slot.binding, &size);
        taken_.push_back({slot.target, slot.binding, name, start, size, slot.resource});
        glBindBufferBase(slot.target, slot.binding, 0);
    }
}

InputAudit::~InputAudit() {
    GLint active = GL_TEXTURE0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    for (const Taken& taken : taken_) {
        if (taken.target == GL_TEXTURE_2D_ARRAY) {
            glActiveTexture(GLenum(GL_TEXTURE0 + taken.binding));
            glBindTexture(GL_TEXTURE_2D_ARRAY, GLuint(taken.name));
        } else if (taken.size > 0) {
            glBindBufferRange(taken.target, taken.binding, GLuint(taken.name), GLintptr(taken.start),
                              GLsizeiptr(taken.size));
        } else {
            glBindBufferBase(taken.target, taken.binding, GLuint(taken.name));
        }
    }
    glActiveTexture(GLenum(active));
}

std::string InputAudit::undeclaredReads() const {
    std::string problems;
    auto problem = [&](const std::string& verb, const Resource& resource, GLenum slot, int binding) {
        problems += (problems.empty() ? "" : "; ") + pass_.name() + " " + verb + " " + resourceName(resource) + " (" +
                    slotName(slot) + " " + std::to_string(binding) + "), which it does not declare";
    };
    GLint active = GL_TEXTURE0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    for (int unit = 0; unit < kTextureUnitCount; ++unit) {
        std::vector<Resource> held = targetsHolding(context_.targets, boundTexture(GL_TEXTURE_2D, unit));
        if (!held.empty() && std::none_of(held.begin(), held.end(), [&](const Resource& t) { return samples(t); }))
            problem("samples", held.front(), GL_TEXTURE_2D, unit);
    }
    for (const InputBinding& row : kInputBindings)
        if (row.slot == InputSlot::TextureArray && !touches(row.resource) &&
            boundTexture(GL_TEXTURE_2D_ARRAY, row.binding) != 0)
            problem("samples", row.resource, GL_TEXTURE_2D_ARRAY, row.binding);
    glActiveTexture(GLenum(active));
    for (const BufferSlot& slot : bufferSlots())
        if (!touches(slot.resource) && boundBuffer(slot.target, slot.binding) != 0)
            problem("reads", slot.resource, slot.target, int(slot.binding));
    return problems;
}

bool InputAudit::samples(const Resource& target) const {
    return std::any_of(declared_.begin(), declared_.end(),
                       [&](const Access& access) { return access.use == Use::Sample && access.resource == target; });
}

bool InputAudit::touches(const Resource& resource) const {
    return std::any_of(declared_.begin(), declared_.end(),
                       [&](const Access& access) { return access.resource == resource; });
}

}  // namespace oasis
