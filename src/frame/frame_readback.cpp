// What the renderer's last frame left, read back (frame/frame_readback.h).
#include "frame/frame_readback.h"

#include <stdexcept>
#include <string>

#include "gl/objects.h"
#include "render/depth_stencil_readback.h"
#include "render/pixel_readback.h"
#include "render/texture_units.h"

namespace oasis {

// The renderer's internals these reads need, and nothing else of it (a friend of Renderer).
struct ReadbackAccess {
    static GLuint waterBounds(const Renderer& renderer) { return renderer.water_.bounds.name(); }
    static GLuint frameBlock(const Renderer& renderer) { return renderer.frameUniforms_.name(); }
    static GLuint lightList(const Renderer& renderer) { return renderer.lights_.list.name(); }
    static GLuint lightCount(const Renderer& renderer) { return renderer.lights_.count.name(); }
    static FloatReadback& positions(Renderer& renderer) { return renderer.positionsReadback_; }
    static void fillSurfacesWithTheirDepth(Renderer& renderer) { renderer.fillSurfacesWithTheirDepth(); }
    // The depth and stencil read-backs may draw (render/depth_stencil_readback.h): a const read
    // of the frame still builds their programs.
    static ShaderLibrary& shaders(const Renderer& renderer) { return renderer.shaders_; }
};

glm::ivec4 readWaterBounds(const Renderer& renderer) {
    glm::ivec4 bounds(1, 1, 0, 0);
    if (!renderer.paths().waterBoundsAvailable) return bounds;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, ReadbackAccess::waterBounds(renderer));
    gl::readBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(bounds), &bounds);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    return bounds;
}

FrameData readFrameBlock(const Renderer& renderer) {
    FrameData data;
    glBindBuffer(GL_UNIFORM_BUFFER, ReadbackAccess::frameBlock(renderer));
    gl::readBufferData(GL_UNIFORM_BUFFER, sizeof(data), &data);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
    return data;
}

std::vector<PointLight> readLightList(const Renderer& renderer) {
    GLuint count[4] = {0, 0, 0, 0};
    glBindBuffer(GL_UNIFORM_BUFFER, ReadbackAccess::lightCount(renderer));
    gl::readBufferData(GL_UNIFORM_BUFFER, sizeof(count), count);
    std::vector<PointLight> lights(count[0]);
    glBindBuffer(GL_UNIFORM_BUFFER, ReadbackAccess::lightList(renderer));
    gl::readBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(lights.size() * sizeof(PointLight)), lights.data());
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
    return lights;
}

void requireHeldAfterFrame(const FrameTargets& targets, Target target) {
    const Target holder = targets.holderAfterFrame(target);
    if (holder != target)
        throw std::logic_error(std::string("the frame lent ") + targetName(target) + "'s memory to " +
                               targetName(holder) + " after its last use: what it held is gone (name what is "
                               "read after the frame in its sink: Renderer::views().setSink)");
}

Image readDisplay(const Renderer& renderer) {
    const FrameTargets& targets = renderer.targets();
    Image image(targets.width(), targets.height());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.displayFramebuffer());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    image.flipRows();  // GL is bottom-up; images are top-down
    return image;
}

void showImage(Renderer& renderer, const Image& image) {
    const FrameTargets& targets = renderer.targets();
    if (image.width != targets.width() || image.height != targets.height())
        throw std::invalid_argument("showImage: the image is not the frame's size");
    Image rows = image;
    rows.flipRows();  // GL's rows are bottom-up
    glBindTexture(GL_TEXTURE_2D, targets.displayTexture());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, rows.rgba.data());
    glBindTexture(GL_TEXTURE_2D, 0);
}

std::vector<float> readTarget(Renderer& renderer, Target target) {
    if (target == Target::Radiance) renderer.views().ensureRadiance();
    const FrameTargets& targets = renderer.targets();
    if (target == Target::DepthStencil || target == Target::SceneDepth)
        throw std::invalid_argument(std::string("readTarget reads colour targets; ") + targetName(target) +
                                    " is read with readDepth()");
    if (!targets.layout().stores(target))
        throw std::invalid_argument(std::string("the ") + targets.layout().name + " G-buffer layout has no " +
                                    targetName(target) + " target");
    requireHeldAfterFrame(targets, target);
    std::vector<float> pixels(size_t(targets.width()) * size_t(targets.height()) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.framebuffer({target}));
    readColourFloats(targets.width(), targets.height(), pixels.data());
    return pixels;
}

std::vector<float> readSurfacePositions(Renderer& renderer) {
    ReadbackAccess::fillSurfacesWithTheirDepth(renderer);
    const FrameTargets& targets = renderer.targets();
    FloatReadback& positions = ReadbackAccess::positions(renderer);
    positions.bindForDrawing(targets.width(), targets.height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    bindGBufferInputs(targets);
    glUseProgram(renderer.parts().shaders.program(targets.layout().program("gbuffer.positions")));
    renderer.parts().geometry.drawFullscreenTriangle();
    return positions.read();
}

namespace {
bool drawsDepthStencil(const Renderer& renderer) { return !renderer.paths().capabilities.depthStencilRead.available; }
}  // namespace

std::vector<float> readDepth(const Renderer& renderer) {
    const FrameTargets& targets = renderer.targets();
    requireHeldAfterFrame(targets, Target::DepthStencil);
    return readDepthRegion(ReadbackAccess::shaders(renderer), targets, wholeDepthStencil(targets, drawsDepthStencil(renderer)));
}

std::vector<uint8_t> readStencil(const Renderer& renderer) {
    const FrameTargets& targets = renderer.targets();
    requireHeldAfterFrame(targets, Target::DepthStencil);
    return readStencilRegion(ReadbackAccess::shaders(renderer), targets, wholeDepthStencil(targets, drawsDepthStencil(renderer)));
}

}  // namespace oasis
