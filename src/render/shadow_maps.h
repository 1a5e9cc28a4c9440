// The sun's cascaded shadow maps on the GPU: one 32-bit float depth texture array (a layer per
// cascade) with depth comparison on, read by common/shadows.glsl as a sampler2DArrayShadow (GL
// 3.3 core and OpenGL ES 3.0 have both), and a depth-only framebuffer per layer for ShadowPass to draw into.
#pragma once
#include <vector>

#include "gl/objects.h"

namespace oasis {

class ShadowMaps {
public:
    ShadowMaps();  // a 1x1 single layer, so the shaders' sampler is complete before any frame

    // (Re)allocates when the size or the layer count changes; the maps' contents are then undefined.
    void ensure(int mapSize, int layers);
    int mapSize() const { return size_; }
    int layers() const { return layers_; }
    GLuint framebuffer(int layer) const { return framebuffers_[size_t(layer)].name(); }
    GLuint texture() const { return texture_.name(); }
    // Binds the array to its texture unit (render/texture_units.h's kUnitShadowMap).
    void bind() const;
    // Whether ShadowPass draws with GL_DEPTH_CLAMP: false where the shaders' dialect flattens the
    // casters instead (OASIS_NO_DEPTH_CLAMP, common/shadow_caster.glsl); set by the renderer.
    bool depthClamp() const { return depthClamp_; }
    void setDepthClamp(bool on) { depthClamp_ = on; }

private:
    gl::Texture texture_;
    std::vector<gl::Framebuffer> framebuffers_;
    int size_ = 0, layers_ = 0;
    bool depthClamp_ = true;
};

}  // namespace oasis
