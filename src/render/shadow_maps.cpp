// Allocation of the shadow map array and its per-layer framebuffers (see shadow_maps.h).
#include "render/shadow_maps.h"

#include <string>

#include "render/texture_units.h"

namespace oasis {

ShadowMaps::ShadowMaps() { ensure(1, 1); }

void ShadowMaps::ensure(int mapSize, int layers) {
    if (mapSize == size_ && layers == layers_) return;
    GLuint name = 0;
    glGenTextures(1, &name);
    texture_ = gl::Texture(name);
    glBindTexture(GL_TEXTURE_2D_ARRAY, name);
    gl::setLabel(texture_, "sun shadow maps (" + std::to_string(layers) + " cascades of " + std::to_string(mapSize) +
                               "^2)");
    // glTexImage3D rather than immutable storage: GL 3.3 contexts have no glTexStorage3D.
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT32F, mapSize, mapSize, layers, 0, GL_DEPTH_COMPONENT,
                 GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
    // Linear filtering with comparison: every lookup is a 2x2 percentage-closer filter.
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    framebuffers_.clear();
    for (int layer = 0; layer < layers; ++layer) {
        framebuffers_.push_back(gl::createFramebuffer("shadow cascade " + std::to_string(layer)));
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffers_.back().name());
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, name, 0, layer);
        const GLenum none = GL_NONE;
        glDrawBuffers(1, &none);  // glDrawBuffer is desktop-only; this is the same on both APIs
        glReadBuffer(GL_NONE);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    size_ = mapSize;
    layers_ = layers;
    bind();
}

void ShadowMaps::bind() const {
    glActiveTexture(GL_TEXTURE0 + kUnitShadowMap);
    glBindTexture(GL_TEXTURE_2D_ARRAY, texture_.name());
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace oasis
