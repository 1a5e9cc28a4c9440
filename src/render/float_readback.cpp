// The float read-back target.
#include "render/float_readback.h"

namespace oasis {

void FloatReadback::bindForDrawing(int width, int height) {
    if (!texture_ || width != width_ || height != height_) {
        texture_ = gl::createTargetTexture("float read-back", GL_RGBA32F, width, height);
        framebuffer_ = gl::createFramebuffer("float read-back");
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.name());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_.name(), 0);
        width_ = width;
        height_ = height;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.name());
    glViewport(0, 0, width, height);
}

std::vector<float> FloatReadback::read() const {
    std::vector<float> pixels(size_t(width_) * size_t(height_) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.name());
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, pixels.data());
    return pixels;
}

}  // namespace oasis
