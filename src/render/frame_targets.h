// The textures a frame renders into and the framebuffers over them. Both pipelines share them:
// deferred fills the G-buffer then lights it into Radiance; forward shades into Radiance directly;
// the mirrored scene goes to Reflection; tone mapping writes Final. Depth-stencil is shared by all.
// Display holds what a debug view shows (or the overview), ready to present or save.
// A target's texture is made at its first use, not up front (issue 43 item 1: a forward frame holds
// no G-buffer), and the frame graph's plan (render/target_aliasing.h) gives back the textures of
// targets a frame does not use and lets targets whose lifetimes do not overlap share one. Textures
// given back wait in a pool for a few frames, so frames that alternate (compare's forward and
// deferred rounds) do not allocate each time. Targets are held at a scale of the frame's size too
// (1/2, 1/4: the reflection drawn reduced, render/frame_resource.h's ScaledTarget): a target at a
// scale is its own resource with its own lifetime, and only targets of one size share memory.
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
#include "render/target_aliasing.h"

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

    // The size of the targets at 1/divisor of the frame (1, 2 or 4), rounded up.
    int width(int divisor = 1) const { return scaleOf(divisor).width; }
    int height(int divisor = 1) const { return scaleOf(divisor).height; }
    const GBufferLayout& layout() const { return layout_; }
    // How the depth-stencil target is stored and compared: every pass takes its depth state here.
    const DepthConvention& depth() const { return depth_; }

    // The texture of `target` at 1/divisor, made (or taken from the pool) at its first use; 0 where
    // the layout does not store it. Targets the plan aliases return the same texture.
    GLuint texture(Target target, int divisor = 1) const;
    // The texture `target` holds now without making one (0 if none): for audits and tests.
    GLuint heldTexture(Target target, int divisor = 1) const;
    // The frame's plan: the targets `lifetimes` names keep (or will make) their textures, aliased
    // as aliasTargets says among the targets of one scale; every other target's texture goes back
    // to the pool. Pool textures unused for kPoolFrames plans are deleted.
    void plan(const std::vector<TargetLifetime>& lifetimes);
    const TargetMemory& memory(int divisor = 1) const { return scaleOf(divisor).memory; }
    // The sampler a target at a reduced scale is read with (bilinear, clamped at its edges: the
    // upsample's taps), bound on its unit beside it: a texture's own state would go with its memory.
    GLuint upsamplingSampler() const { return upsampling_.name(); }
    // The target whose values `target`'s texture holds after the frame: `target` itself, unless
    // the plan lent its memory to a target used after it (what it held is then gone).
    Target holderAfterFrame(Target target) const;
    // The GPU memory the targets hold now: each texture held (aliased ones once, Display included)
    // at its format's bytes per texel. The pool's waiting textures are not counted (pooledBytes).
    double heldBytes() const;
    double pooledBytes() const;
    static constexpr int kPoolFrames = 4;
    // The G-buffer framebuffer's colour attachment (and draw buffer) of a stored target: the
    // stored ones in kGBufferColourTargets order, no gaps. -1 for a target it does not hold.
    int gbufferSlot(Target target) const;
    int gbufferSlotCount() const { return gbufferSlot(Target::Info) + 1; }
    // Display, made at its first use: its own texture always. (Lent the memory of an RGBA8 target
    // that ends inside the frame, it changed views' pictures after frames of another sink,
    // FrameSink.EveryViewIsTheSameAfterItsOwnFrameAsAfterAWholeFrame, for a reason not found yet.)
    GLuint displayTexture() const;
    // The framebuffer over `colour` (attachments 0.. in that order, the targets this layout does not
    // store left out, so the draw buffers have no gaps: zink leaves every column past 1024
    // unrendered at 1280x720 when one in the middle is GL_NONE) and `depth` (DepthStencil or
    // SceneDepth), made on first use and kept: passes bind the one of their declared writes.
    // 0 where the layout stores none of them. With a divisor, over those targets at 1/divisor.
    GLuint framebuffer(const std::vector<Target>& colour, std::optional<Target> depth = std::nullopt,
                       int divisor = 1) const;
    // The G-buffer's stored colour targets in kGBufferColourTargets order.
    std::vector<Target> gbufferColourTargets() const;
    GLuint displayFramebuffer() const;

private:
    GBufferLayout layout_;
    DepthConvention depth_;
    // The targets at one scale of the frame: 1, 1/2, 1/4 (kDivisors).
    struct Scale {
        int divisor = 1;
        int width = 0, height = 0;
        // The textures held, by the target whose memory they are (memory); aliased targets hold none.
        std::array<gl::Texture, size_t(Target::Count)> textures;
        TargetMemory memory;
        TargetMemory holderAfterFrame;  // by memory: its last holder in the plan
    };
    static constexpr int kDivisors[] = {1, 2, 4};
    mutable std::array<Scale, 3> scales_;
    const Scale& scaleOf(int divisor) const;
    struct Pooled {
        gl::Texture texture;
        unsigned format;
        int bytesPerPixel;
        int width, height;
        Target lastHolder;  // given back to the same target first, so its contents stay where they were
        int idlePlans;
    };
    mutable std::vector<Pooled> pool_;
    mutable gl::Texture display_;
    gl::Sampler upsampling_;
    std::string labelPrefix_;
    // Keyed by the textures attached, since a target's texture changes with the plan.
    using FramebufferKey = std::pair<std::vector<GLuint>, GLuint>;
    mutable std::map<FramebufferKey, gl::Framebuffer> framebuffers_;
    void giveBack(Scale& scale, Target memory);
    void planScale(Scale& scale, const std::vector<TargetLifetime>& lifetimes);
    void forgetFramebuffersOf(GLuint texture);
};

}  // namespace oasis
