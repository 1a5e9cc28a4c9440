// What the renderer's last frame left, read back for tests and tools (frame/renderer.h): the
// Display image, a colour target, the surfaces' positions, depth, stencil and the water's bounds;
// and an image put into Display for present() to show. Each read is a stall.
#include "frame/renderer.h"

#include <stdexcept>
#include <string>

#include "gl/objects.h"
#include "render/pixel_readback.h"
#include "render/texture_units.h"

namespace oasis {

glm::ivec4 Renderer::readWaterBounds() const {
    glm::ivec4 bounds(1, 1, 0, 0);
    if (!paths_.waterBoundsAvailable) return bounds;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, waterBounds_.name());
    gl::readBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(bounds), &bounds);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    return bounds;
}

Image Renderer::readDisplay() const {
    Image image(targets_->width(), targets_->height());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets_->displayFramebuffer());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    image.flipRows();  // GL is bottom-up; images are top-down
    return image;
}

void Renderer::showImage(const Image& image) {
    if (image.width != targets_->width() || image.height != targets_->height())
        throw std::invalid_argument("showImage: the image is not the frame's size");
    Image rows = image;
    rows.flipRows();  // GL's rows are bottom-up
    glBindTexture(GL_TEXTURE_2D, targets_->displayTexture());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, rows.rgba.data());
    glBindTexture(GL_TEXTURE_2D, 0);
}

std::vector<float> Renderer::readTarget(Target target) {
    if (target == Target::Radiance) ensureRadiance();
    if (target == Target::DepthStencil || target == Target::SceneDepth)
        throw std::invalid_argument(std::string("readTarget reads colour targets; ") + targetName(target) +
                                    " is read with readDepth()");
    if (!targets_->layout().stores(target))
        throw std::invalid_argument(std::string("the ") + targets_->layout().name + " G-buffer layout has no " +
                                    targetName(target) + " target");
    std::vector<float> pixels(size_t(targets_->width()) * size_t(targets_->height()) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets_->framebuffer({target}));
    readColourFloats(targets_->width(), targets_->height(), pixels.data());
    return pixels;
}

std::vector<float> Renderer::readSurfacePositions() {
    // After a whole frame the water composite has written the water's depth over the mirrored
    // scene the G-buffer holds there. A layout that rebuilds positions from depth reads them from
    // those surfaces refilled with their own depth: the mirrored view fill, what the frame left.
    if (targets_->layout().positionFromDepth() && stoppedBefore_.empty() && !gbufferHolds_) {
        WaterScene asked = viewWaterScene_;
        viewWaterScene_ = WaterScene::Mirrored;
        ensureGBuffer();
        viewWaterScene_ = asked;
    }
    positionsReadback_.bindForDrawing(targets_->width(), targets_->height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    bindGBufferInputs(*targets_);
    glUseProgram(shaders_.program(targets_->layout().program("gbuffer.positions")));
    geometry_.drawFullscreenTriangle();
    return positionsReadback_.read();
}

std::vector<float> Renderer::readDepth() const {
    std::vector<float> depth(size_t(targets_->width()) * size_t(targets_->height()));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets_->framebuffer({}, Target::DepthStencil));
    readDepthFloats(targets_->width(), targets_->height(), depth.data());
    return depth;
}

std::vector<uint8_t> Renderer::readStencil() const {
    std::vector<uint8_t> stencil(size_t(targets_->width()) * size_t(targets_->height()));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets_->framebuffer({}, Target::DepthStencil));
    readStencilBytes(targets_->width(), targets_->height(), stencil.data());
    return stencil;
}

}  // namespace oasis
