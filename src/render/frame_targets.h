// The textures a frame renders into and the framebuffers over them. Both pipelines share them:
// deferred fills the G-buffer then lights it into Radiance; forward shades into Radiance directly;
// the mirrored scene goes to Reflection; tone mapping writes Final. Depth-stencil is shared by all.
// Display holds what a debug view shows (or the overview), ready to present or save.
#pragma once
#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gl/objects.h"
#include "render/depth_convention.h"
#include "render/gbuffer_layout.h"

namespace oasis {

// Larger frames are refused with a message instead of risking the process on allocation.
constexpr double kMaxTargetBytes = 4.0 * 1024 * 1024 * 1024;

inline constexpr Target kGBufferColourTargets[] = {Target::Albedo, Target::Normal, Target::Position, Target::Info};

class FrameTargets {
public:
    // Throws std::runtime_error when the size is impossible or the framebuffer is incomplete.
    // `purpose` prefixes the labels capture tools list (the reduced reflection's: "reflection at 1/2").
    FrameTargets(const GBufferLayout& layout, const DepthConvention& depth, int width, int height,
                 const std::string& purpose = "");

    int width() const { return width_; }
    int height() const { return height_; }
    const GBufferLayout& layout() const { return layout_; }
    // How the depth-stencil target is stored and compared: every pass takes its depth state here.
    const DepthConvention& depth() const { return depth_; }

    GLuint texture(Target target) const { return textures_[size_t(target)].name(); }
    // The G-buffer framebuffer's colour attachment (and draw buffer) of a stored target: the
    // stored ones in kGBufferColourTargets order, no gaps. -1 for a target it does not hold.
    int gbufferSlot(Target target) const;
    int gbufferSlotCount() const { return gbufferSlot(Target::Info) + 1; }
    GLuint displayTexture() const { return display_.name(); }
    // The framebuffer over `colour` (attachments 0.. in that order, the targets this layout does not
    // store left out, so the draw buffers have no gaps: zink leaves every column past 1024
    // unrendered at 1280x720 when one in the middle is GL_NONE) and `depth` (DepthStencil or
    // SceneDepth), made on first use and kept: passes bind the one of their declared writes.
    // 0 where the layout stores none of them.
    GLuint framebuffer(const std::vector<Target>& colour, std::optional<Target> depth = std::nullopt) const;
    // The G-buffer's stored colour targets in kGBufferColourTargets order.
    std::vector<Target> gbufferColourTargets() const;
    GLuint displayFramebuffer() const { return displayFbo_.name(); }

private:
    GBufferLayout layout_;
    DepthConvention depth_;
    int width_, height_;
    std::array<gl::Texture, size_t(Target::Count)> textures_;
    gl::Texture display_;
    std::string labelPrefix_;
    gl::Framebuffer displayFbo_;
    using FramebufferKey = std::pair<std::vector<Target>, std::optional<Target>>;
    mutable std::map<FramebufferKey, gl::Framebuffer> framebuffers_;
};

}  // namespace oasis
