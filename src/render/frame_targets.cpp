// Allocation of the frame's render targets.
#include "render/frame_targets.h"

#include <algorithm>
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

// What capture tools list a target as: its descriptor's label, after it the layout ("G-buffer
// albedo (compact)") and the depth convention whose format it has.
std::string targetLabel(const GBufferLayout& layout, const DepthConvention& depth, Target target) {
    const TargetDescriptor& row = targetDescriptor(target);
    switch (row.format) {
        case FormatFrom::LayoutRow: return std::string(row.label) + " (" + layout.name + ")";
        case FormatFrom::Depth: return std::string(row.label) + " (" + layout.name + ", " + depth.name + " depth)";
        default: return row.label;
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
    : layout_(layout), depth_(depth) {
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
    labelPrefix_ = prefix;
    for (size_t k = 0; k < scales_.size(); ++k) {
        Scale& scale = scales_[k];
        scale.divisor = kDivisors[k];
        scale.width = (width + scale.divisor - 1) / scale.divisor;
        scale.height = (height + scale.divisor - 1) / scale.divisor;
        scale.memory = unaliasedTargets();
        scale.holderAfterFrame = scale.memory;
    }
    upsampling_ = gl::createSampler("reduced targets: bilinear, clamped");
    glSamplerParameteri(upsampling_.name(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(upsampling_.name(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(upsampling_.name(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(upsampling_.name(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    // The framebuffers every frame binds are made once now, so an incomplete one (a format this
    // context cannot draw into) is refused here; their textures are then let go again, to be made
    // at their first use in a frame.
    framebuffer(gbufferColourTargets(), Target::DepthStencil);
    framebuffer({Target::Radiance}, Target::DepthStencil);
    framebuffer({Target::Reflection}, Target::DepthStencil);
    framebuffer({Target::Final});
    framebuffers_.clear();
    for (gl::Texture& texture : scales_[0].textures) texture.reset();
}

const FrameTargets::Scale& FrameTargets::scaleOf(int divisor) const {
    for (const Scale& scale : scales_)
        if (scale.divisor == divisor) return scale;
    throw std::logic_error("no frame targets at 1/" + std::to_string(divisor) + " of the frame");
}

GLuint FrameTargets::heldTexture(Target target, int divisor) const {
    if (!layout_.stores(target)) return 0;
    const Scale& scale = scaleOf(divisor);
    return scale.textures[size_t(scale.memory[size_t(target)])].name();
}

GLuint FrameTargets::texture(Target target, int divisor) const {
    if (!layout_.stores(target)) return 0;
    Scale& scale = const_cast<Scale&>(scaleOf(divisor));  // scales_ is mutable: textures made on use
    const Target memory = scale.memory[size_t(target)];
    gl::Texture& held = scale.textures[size_t(memory)];
    if (held.name()) return held.name();
    const TargetFormat format = targetFormat(layout_, depth_, memory);
    const int width = scale.width, height = scale.height;
    // What capture tools list it as: the reduced reflection's prefixed by their scale.
    const std::string prefix = labelPrefix_ + (divisor == 1 ? "" : "reflection at 1/" + std::to_string(divisor) + ": ");
    // The pool's texture of the same format and size, the one this target held before if it is there.
    auto pooled = pool_.end();
    for (auto entry = pool_.begin(); entry != pool_.end(); ++entry)
        if (entry->format == unsigned(format.internalFormat) && entry->width == width && entry->height == height &&
            (pooled == pool_.end() || entry->lastHolder == memory))
            pooled = entry;
    if (pooled != pool_.end()) {
        held = std::move(pooled->texture);
        pool_.erase(pooled);
    } else {
        // Made in the middle of a pass's bindings: the active unit's texture is put back after.
        GLint bound = 0;
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
        while (glGetError() != GL_NO_ERROR) {}
        held = gl::createTargetTexture(prefix + targetLabel(layout_, depth_, memory), format.internalFormat,
                                       width, height);
        if (GLenum error = glGetError(); error != GL_NO_ERROR)
            throw std::runtime_error("allocating a " + std::to_string(width) + "x" + std::to_string(height) + " " +
                                     targetName(memory) + " target failed: " + gl::errorString(error));
        glBindTexture(GL_TEXTURE_2D, GLuint(bound));
    }
    // Labelled by every target it is lent to this frame, as capture tools list it.
    std::string label = prefix + targetLabel(layout_, depth_, memory);
    for (int t = 0; t < int(Target::Count); ++t)
        if (Target(t) != memory && scale.memory[t] == memory) label += " + " + std::string(targetName(Target(t)));
    gl::setLabel(held, label);
    return held.name();
}

void FrameTargets::giveBack(Scale& scale, Target memory) {
    gl::Texture& held = scale.textures[size_t(memory)];
    if (!held.name()) return;
    const TargetFormat format = targetFormat(layout_, depth_, memory);
    pool_.push_back(
        {std::move(held), unsigned(format.internalFormat), format.bytesPerPixel, scale.width, scale.height, memory, 0});
}

void FrameTargets::forgetFramebuffersOf(GLuint texture) {
    for (auto entry = framebuffers_.begin(); entry != framebuffers_.end();) {
        const auto& [colour, depth] = entry->first;
        if (depth == texture || std::find(colour.begin(), colour.end(), texture) != colour.end())
            entry = framebuffers_.erase(entry);
        else
            ++entry;
    }
}

void FrameTargets::plan(const std::vector<TargetLifetime>& lifetimes) {
    for (auto& entry : pool_) ++entry.idlePlans;
    // Only targets of one size share memory: each scale is planned alone.
    for (Scale& scale : scales_) {
        std::vector<TargetLifetime> ofScale;
        for (const TargetLifetime& lifetime : lifetimes)
            if (lifetime.divisor == scale.divisor) ofScale.push_back(lifetime);
        planScale(scale, ofScale);
    }
    for (auto entry = pool_.begin(); entry != pool_.end();) {
        if (entry->idlePlans > kPoolFrames) {
            forgetFramebuffersOf(entry->texture.name());
            entry = pool_.erase(entry);
        } else {
            ++entry;
        }
    }
}

void FrameTargets::planScale(Scale& scale, const std::vector<TargetLifetime>& lifetimes) {
    // Readers after the frame are in its graph (Renderer::requestGraph): their targets live to
    // kBeyondFrame and lend nothing, so a target lends its memory only where nothing reads it again.
    const TargetMemory memory = aliasTargets(lifetimes, [&](Target target) {
        return unsigned(targetFormat(layout_, depth_, target).internalFormat);
    });
    // Each memory's last holder: the target whose values it holds when the frame ends.
    std::array<int, size_t(Target::Count)> latestFirst;
    latestFirst.fill(-1);
    scale.holderAfterFrame = unaliasedTargets();
    for (const TargetLifetime& lifetime : lifetimes) {
        const size_t owner = size_t(memory[size_t(lifetime.target)]);
        if (lifetime.first > latestFirst[owner]) {
            latestFirst[owner] = lifetime.first;
            scale.holderAfterFrame[owner] = lifetime.target;
        }
    }
    std::array<bool, size_t(Target::Count)> used{};
    for (const TargetLifetime& lifetime : lifetimes) used[size_t(lifetime.target)] = true;
    // A memory changes hands when the aliasing changes: every texture goes back and is taken again
    // at its first use (mostly the same one, by lastHolder). Otherwise only unused targets' go back.
    const bool realiased = memory != scale.memory;
    for (int t = 0; t < int(Target::Count); ++t)
        if (realiased || !used[t]) giveBack(scale, Target(t));
    scale.memory = memory;
}

Target FrameTargets::holderAfterFrame(Target target) const {
    const Scale& frame = scales_[0];
    return frame.holderAfterFrame[size_t(frame.memory[size_t(target)])];
}

double FrameTargets::heldBytes() const {
    double bytes = display_.name() ? 4.0 * width() * height() : 0.0;  // Display, RGBA8
    for (const Scale& scale : scales_)
        for (int t = 0; t < int(Target::Count); ++t)
            if (scale.textures[t].name())
                bytes += double(targetFormat(layout_, depth_, Target(t)).bytesPerPixel) * scale.width * scale.height;
    return bytes;
}

double FrameTargets::pooledBytes() const {
    double bytes = 0.0;
    for (const Pooled& entry : pool_) bytes += double(entry.bytesPerPixel) * entry.width * entry.height;
    return bytes;
}

GLuint FrameTargets::displayTexture() const {
    if (!display_.name()) {
        GLint bound = 0;  // as texture(): the active unit's texture is put back
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
        display_ = gl::createTargetTexture(labelPrefix_ + "Display", GL_RGBA8, width(), height());
        glBindTexture(GL_TEXTURE_2D, GLuint(bound));
    }
    return display_.name();
}

GLuint FrameTargets::displayFramebuffer() const {
    const GLuint display = displayTexture();
    FramebufferKey key{{display}, 0};
    if (auto found = framebuffers_.find(key); found != framebuffers_.end()) return found->second.name();
    gl::Framebuffer fbo = gl::createFramebuffer(labelPrefix_ + "Display: debug views");
    GLint previous = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.name());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, display, 0);
    const GLenum colour0 = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &colour0);
    checkComplete("display");
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    GLuint name = fbo.name();
    framebuffers_.emplace(std::move(key), std::move(fbo));
    return name;
}

GLuint FrameTargets::framebuffer(const std::vector<Target>& colour, std::optional<Target> depth, int divisor) const {
    std::vector<Target> stored;
    for (Target target : colour)
        if (layout_.stores(target)) stored.push_back(target);
    // The depth attachment, where the layout stores it (a plain value: GCC warned the optional's
    // value may be read uninitialised).
    const bool hasDepth = depth.has_value() && layout_.stores(*depth);
    const Target depthTarget = depth.value_or(Target::DepthStencil);
    if (stored.empty() && !hasDepth) return 0;  // nothing this layout stores (SceneDepth in full)
    FramebufferKey key{{}, hasDepth ? texture(depthTarget, divisor) : 0};
    for (Target target : stored) key.first.push_back(texture(target, divisor));
    if (auto found = framebuffers_.find(key); found != framebuffers_.end()) return found->second.name();
    // Labelled by what it holds, as capture tools list it: "Radiance, Final + DepthStencil".
    std::string label;
    for (Target target : stored) label += (label.empty() ? "" : ", ") + std::string(targetName(target));
    if (hasDepth) label += (label.empty() ? "" : " + ") + std::string(targetName(depthTarget));
    if (divisor != 1) label = "reflection at 1/" + std::to_string(divisor) + ": " + label;
    gl::Framebuffer fbo = gl::createFramebuffer(labelPrefix_ + label);
    GLint previous = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.name());
    std::vector<GLenum> drawBuffers;
    for (Target target : stored) {
        GLenum attachment = GLenum(GL_COLOR_ATTACHMENT0 + drawBuffers.size());
        glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture(target, divisor), 0);
        drawBuffers.push_back(attachment);
    }
    if (hasDepth)
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, texture(depthTarget, divisor),
                               0);
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
