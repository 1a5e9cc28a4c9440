// Read-backs that work on desktop GL and OpenGL ES (see pixel_readback.h).
#include "render/pixel_readback.h"

#include <vector>

namespace oasis {
namespace {

GLint attachmentParameter(GLenum attachment, GLenum parameter) {
    GLint value = 0;
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment, parameter, &value);
    return value;
}

GLenum readBufferAttachment() {
    GLint buffer = GL_COLOR_ATTACHMENT0;
    glGetIntegerv(GL_READ_BUFFER, &buffer);
    return GLenum(buffer);
}

bool floatDepth() {
    return attachmentParameter(GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE) == GL_FLOAT;
}

}  // namespace

void readColourFloats(int width, int height, float* out) {
    size_t count = size_t(width) * size_t(height) * 4;
    GLenum attachment = readBufferAttachment();
    if (epoxy_is_desktop_gl() ||
        attachmentParameter(attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE) == GL_FLOAT) {
        glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, out);
        return;
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    if (attachmentParameter(attachment, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE) > 8) {  // RG16 (EXT_texture_norm16)
        std::vector<uint16_t> shorts(count);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_SHORT, shorts.data());
        for (size_t i = 0; i < count; ++i) out[i] = float(shorts[i]) / 65535.0f;
        return;
    }
    std::vector<uint8_t> bytes(count);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    for (size_t i = 0; i < count; ++i) out[i] = float(bytes[i]) / 255.0f;
}

void readDepthFloats(int x, int y, int width, int height, float* out) {
    size_t count = size_t(width) * size_t(height);
    if (epoxy_is_desktop_gl()) {
        glReadPixels(x, y, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, out);
        return;
    }
    if (floatDepth()) {  // D32F_S8: the float and the stencil word of each pixel
        std::vector<uint32_t> words(count * 2);
        glReadPixels(x, y, width, height, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, words.data());
        for (size_t i = 0; i < count; ++i) out[i] = reinterpret_cast<const float*>(words.data())[2 * i];
        return;
    }
    std::vector<uint32_t> packed(count);  // D24S8: depth in the high 24 bits
    glReadPixels(x, y, width, height, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed.data());
    for (size_t i = 0; i < count; ++i) out[i] = float(double(packed[i] >> 8) / 16777215.0);
}

void readStencilBytes(int x, int y, int width, int height, uint8_t* out) {
    size_t count = size_t(width) * size_t(height);
    if (epoxy_is_desktop_gl()) {
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(x, y, width, height, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, out);
        return;
    }
    if (floatDepth()) {
        std::vector<uint32_t> words(count * 2);
        glReadPixels(x, y, width, height, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, words.data());
        for (size_t i = 0; i < count; ++i) out[i] = uint8_t(words[2 * i + 1] & 0xFF);
        return;
    }
    std::vector<uint32_t> packed(count);
    glReadPixels(x, y, width, height, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed.data());
    for (size_t i = 0; i < count; ++i) out[i] = uint8_t(packed[i] & 0xFF);
}

}  // namespace oasis
