// Allocation of the frame's render targets.
#include "render/frame_targets.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace oasis {
namespace {

void checkComplete(const char* what) {
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string(what) + " framebuffer incomplete (status 0x" +
                                 std::to_string(status) + ")");
}

// One decimal, rounded up, so a size just over the limit never reads as the limit itself.
std::string gibibytes(double bytes) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.1f", std::ceil(bytes / double(1u << 30) * 10.0) / 10.0);
    return text;
}

// What capture tools list a target as: the G-buffer's by role and layout ("G-buffer albedo
// (compact)"), its depth-stencil also by depth convention; the others by role.
std::string targetLabel(const GBufferLayout& layout, const DepthConvention& depth, Target target) {
    switch (target) {
        case Target::DepthStencil:
            return "G-buffer depth-stencil (" + layout.name + ", " + depth.name + " depth)";
        case Target::Radiance: return "Radiance";
        case Target::Reflection: return "Reflection";
        case Target::Final: return "Final";
        case Target::SceneDepth: return "SceneDepth copy";
        default: return std::string("G-buffer ") + targetName(target) + " (" + layout.name + ")";
    }
}

int bytesPerPixelOfAllTargets(const GBufferLayout& layout, const DepthConvention& depth) {
    int total = 4;  // Display
    for (int t = 0; t < int(Target::Count); ++t) total += targetFormat(layout, depth, Target(t)).bytesPerPixel;
    return total;
}

}  // namespace

FrameTargets::FrameTargets(const GBufferLayout& layout, const DepthConvention& depth, int width, int height,
                           const std::string& purpose)
    : layout_(layout), depth_(depth), width_(width), height_(height) {
    const std::string prefix = purpose.empty() ? "" : purpose + ": ";
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (width < 1 || height < 1 || width > maxSize || height > maxSize)
        throw std::runtime_error("frame size " + std::to_string(width) + "x" + std::to_string(height) +
                                 " is outside 1.." + std::to_string(maxSize) +
                                 " (GL_MAX_TEXTURE_SIZE of this driver)");
    // Software drivers allocate targets in system memory and may abort rather than report
    // GL_OUT_OF_MEMORY: refuse sizes whose targets could not reasonably fit.
    double bytes = double(width) * double(height) * double(bytesPerPixelOfAllTargets(layout, depth));
    if (bytes > kMaxTargetBytes)
        throw std::runtime_error("frame size " + std::to_string(width) + "x" + std::to_string(height) + " needs " +
                                 gibibytes(bytes) + " GiB of render targets (" +
                                 layout.name + " layout, " + depth.name + " depth); the limit is " +
                                 std::to_string(int(kMaxTargetBytes / double(1u << 30))) + " GiB");
    while (glGetError() != GL_NO_ERROR) {}
    for (int t = 0; t < int(Target::Count); ++t)
        if (layout.stores(Target(t)))
            textures_[t] = gl::createTargetTexture(prefix + targetLabel(layout, depth, Target(t)),
                                                   targetFormat(layout, depth, Target(t)).internalFormat, width, height);
    display_ = gl::createTargetTexture(prefix + "Display", GL_RGBA8, width, height);
    if (GLenum error = glGetError(); error != GL_NO_ERROR)
        throw std::runtime_error("allocating " + std::to_string(width) + "x" + std::to_string(height) +
                                 " render targets failed: " + gl::errorString(error));

    gbufferFbo_ = gl::createFramebuffer(prefix + "G-buffer (" + layout.name + "): geometry passes");
    glBindFramebuffer(GL_FRAMEBUFFER, gbufferFbo_.name());
    // The stored colour targets on consecutive attachments, no gaps (gbuffer.glsl's output
    // locations follow): zink leaves every column past 1024 unrendered at 1280x720 when a draw
    // buffer in the middle is GL_NONE.
    GLenum drawBuffers[4];
    int slots = 0;
    for (Target target : kGBufferColourTargets) {
        if (!layout.stores(target)) continue;
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + slots, GL_TEXTURE_2D, texture(target), 0);
        drawBuffers[slots] = GL_COLOR_ATTACHMENT0 + slots;
        ++slots;
    }
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                           texture(Target::DepthStencil), 0);
    glDrawBuffers(slots, drawBuffers);
    checkComplete("G-buffer");

    auto colourWithDepthStencil = [&](gl::Framebuffer& fbo, Target colour, const char* what, const char* label) {
        fbo = gl::createFramebuffer(prefix + label);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.name());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture(colour), 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                               texture(Target::DepthStencil), 0);
        checkComplete(what);
    };
    colourWithDepthStencil(radianceFbo_, Target::Radiance, "radiance",
                           "Radiance + depth-stencil: lighting, light volumes, forward, water passes");
    colourWithDepthStencil(reflectionFbo_, Target::Reflection, "reflection",
                           "Reflection + depth-stencil: mirrored lighting, forward mirrored passes");

    colourWithDepthStencil(finalDepthFbo_, Target::Final, "final + depth",
                           "Final + depth-stencil: the water composite with the tone map fused");
    auto radianceFinal = [&](gl::Framebuffer& fbo, bool withDepthStencil, const char* what, const char* label) {
        fbo = gl::createFramebuffer(prefix + label);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.name());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture(Target::Radiance), 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, texture(Target::Final), 0);
        if (withDepthStencil)
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                                   texture(Target::DepthStencil), 0);
        const GLenum radianceFinalBuffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glDrawBuffers(2, radianceFinalBuffers);
        checkComplete(what);
    };
    radianceFinal(radianceFinalFbo_, true, "radiance + final", "Radiance, Final + depth-stencil: passes with the tone map fused");
    radianceFinal(radianceFinalOnlyFbo_, false, "radiance + final, no depth",
                  "Radiance, Final: deferred lighting with the tone map fused (samples depth)");
    radianceOnlyFbo_ = gl::createFramebuffer(prefix + "Radiance: deferred lighting (samples depth)");
    glBindFramebuffer(GL_FRAMEBUFFER, radianceOnlyFbo_.name());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture(Target::Radiance), 0);
    checkComplete("radiance, no depth");

    finalFbo_ = gl::createFramebuffer(prefix + "Final: ToneMapPass");
    glBindFramebuffer(GL_FRAMEBUFFER, finalFbo_.name());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture(Target::Final), 0);
    checkComplete("final");

    if (layout.stores(Target::SceneDepth)) {
        sceneDepthFbo_ = gl::createFramebuffer(prefix + "SceneDepth copy: DepthCopyPass");
        glBindFramebuffer(GL_FRAMEBUFFER, sceneDepthFbo_.name());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                               texture(Target::SceneDepth), 0);
        const GLenum none = GL_NONE;
        glDrawBuffers(1, &none);  // glDrawBuffer is desktop-only; this is the same on both APIs
        glReadBuffer(GL_NONE);
        checkComplete("scene depth");
    }

    displayFbo_ = gl::createFramebuffer(prefix + "Display: debug views");
    glBindFramebuffer(GL_FRAMEBUFFER, displayFbo_.name());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, display_.name(), 0);
    checkComplete("display");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

int FrameTargets::gbufferSlot(Target target) const {
    int slot = 0;
    for (Target colour : kGBufferColourTargets) {
        if (!layout_.stores(colour)) continue;
        if (colour == target) return slot;
        ++slot;
    }
    return -1;
}

}  // namespace oasis
