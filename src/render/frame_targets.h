// The textures a frame renders into and the framebuffers over them. Both pipelines share them:
// deferred fills the G-buffer then lights it into Radiance; forward shades into Radiance directly;
// the mirrored scene goes to Reflection; tone mapping writes Final. Depth-stencil is shared by all.
// Display holds what a debug view shows (or the overview), ready to present or save.
#pragma once
#include <array>
#include <string>

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
    GLuint gbufferFramebuffer() const { return gbufferFbo_.name(); }
    GLuint radianceFramebuffer() const { return radianceFbo_.name(); }      // Radiance + depth-stencil
    GLuint reflectionFramebuffer() const { return reflectionFbo_.name(); }  // Reflection + depth-stencil
    GLuint finalFramebuffer() const { return finalFbo_.name(); }            // Final only
    // The fused tone map's outputs: Radiance and Final (draw buffers 0 and 1) + depth-stencil for
    // the passes that shade; Final + depth-stencil for the water composite that reads Radiance.
    GLuint radianceFinalFramebuffer() const { return radianceFinalFbo_.name(); }
    GLuint finalDepthFramebuffer() const { return finalDepthFbo_.name(); }
    // Radiance (and Final) without the depth-stencil target: the direct deferred lighting, which
    // tests neither depth nor stencil and so may sample depth from that target itself.
    GLuint radianceOnlyFramebuffer(bool withFinal) const {
        return withFinal ? radianceFinalOnlyFbo_.name() : radianceOnlyFbo_.name();
    }
    GLuint sceneDepthFramebuffer() const { return sceneDepthFbo_.name(); }  // SceneDepth; 0 if not stored
    GLuint displayFramebuffer() const { return displayFbo_.name(); }

private:
    GBufferLayout layout_;
    DepthConvention depth_;
    int width_, height_;
    std::array<gl::Texture, size_t(Target::Count)> textures_;
    gl::Texture display_;
    gl::Framebuffer gbufferFbo_, radianceFbo_, reflectionFbo_, finalFbo_, displayFbo_, sceneDepthFbo_;
    gl::Framebuffer radianceFinalFbo_, finalDepthFbo_, radianceOnlyFbo_, radianceFinalOnlyFbo_;
};

}  // namespace oasis
