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

    labelPrefix_ = prefix;
    // The framebuffers every frame binds are made now, so an incomplete one is refused here.
    std::vector<Target> gbuffer = gbufferColourTargets();
    framebuffer(gbuffer, Target::DepthStencil);
    framebuffer({Target::Radiance}, Target::DepthStencil);
    framebuffer({Target::Reflection}, Target::DepthStencil);
    framebuffer({Target::Final});

    displayFbo_ = gl::createFramebuffer(prefix + "Display: debug views");
    glBindFramebuffer(GL_FRAMEBUFFER, displayFbo_.name());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, display_.name(), 0);
    checkComplete("display");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

GLuint FrameTargets::framebuffer(const std::vector<Target>& colour, std::optional<Target> depth) const {
    std::vector<Target> stored;
    for (Target target : colour)
        if (layout_.stores(target)) stored.push_back(target);
    if (depth && !layout_.stores(*depth)) depth.reset();
    if (stored.empty() && !depth) return 0;  // nothing this layout stores (SceneDepth in full)
    FramebufferKey key{stored, depth};
    if (auto found = framebuffers_.find(key); found != framebuffers_.end()) return found->second.name();
    // Labelled by what it holds, as capture tools list it: "Radiance, Final + DepthStencil".
    std::string label;
    for (Target target : stored) label += (label.empty() ? "" : ", ") + std::string(targetName(target));
    if (depth) label += (label.empty() ? "" : " + ") + std::string(targetName(*depth));
    gl::Framebuffer fbo = gl::createFramebuffer(labelPrefix_ + label);
    GLint previous = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.name());
    std::vector<GLenum> drawBuffers;
    for (Target target : stored) {
        GLenum attachment = GLenum(GL_COLOR_ATTACHMENT0 + drawBuffers.size());
        glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture(target), 0);
        drawBuffers.push_back(attachment);
    }
    if (depth)
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, texture(*depth), 0);
    if (drawBuffers.empty()) {
        const GLenum none = GL_NONE;
        glDrawBuffers(1, &none);  // glDrawBuffer is desktop-only; this is the same on both APIs
        glReadBuffer(GL_NONE);
    } else {
        glDrawBuffers(GLsizei(drawBuffers.size()), drawBuffers.data());
    }
    checkComplete(label.c_str());
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    GLuint name = fbo.name();
    framebuffers_.emplace(std::move(key), std::move(fbo));
    return name;
}

std::vector<Target> FrameTargets::gbufferColourTargets() const {
    std::vector<Target> stored;
    for (Target colour : kGBufferColourTargets)
        if (layout_.stores(colour)) stored.push_back(colour);
    return stored;
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
