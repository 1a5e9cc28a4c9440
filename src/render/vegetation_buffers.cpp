// Uploads the billboard instances and draws one list of them.
#include "render/vegetation_buffers.h"

#include <cstddef>

#include "render/plant_atlas.h"
#include "render/texture_units.h"

namespace oasis {
namespace {

constexpr GLuint kBaseSizeAttribute = 0, kTintPhaseAttribute = 1, kVariantAttribute = 2;

}  // namespace

VegetationBuffers::VegetationBuffers() {
    vertexArray_ = gl::createVertexArray("vegetation billboards");
    instances_ = gl::createBuffer("vegetation instances");
    atlasSampler_ = gl::createSampler("plant atlas (trilinear)");
    // Trilinear, so a far plant samples a level where its lines still cover a texel; the last
    // level is the atlas's smallest that keeps cells apart.
    glSamplerParameteri(atlasSampler_.name(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glSamplerParameteri(atlasSampler_.name(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(atlasSampler_.name(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(atlasSampler_.name(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glSamplerParameterf(atlasSampler_.name(), GL_TEXTURE_MAX_LOD, float(PlantAtlas::kMipLevels - 1));
    glBindVertexArray(vertexArray_.name());
    for (GLuint attribute : {kBaseSizeAttribute, kTintPhaseAttribute, kVariantAttribute}) {
        glEnableVertexAttribArray(attribute);
        glVertexAttribDivisor(attribute, 1);
    }
    glBindVertexArray(0);
}

void VegetationBuffers::upload(const VegetationDrawList& list) {
    directCount_ = list.directCount;
    mirroredCount_ = list.mirroredCount;
    glBindBuffer(GL_ARRAY_BUFFER, instances_.name());
    GLsizeiptr bytes = GLsizeiptr(list.instances.size() * sizeof(PlantDrawInstance));
    glBufferData(GL_ARRAY_BUFFER, bytes, nullptr, GL_STREAM_DRAW);
    if (bytes > 0) glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, list.instances.data());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void VegetationBuffers::setAtlas(GLuint texture, int columns, int rows) {
    atlas_ = texture;
    columns_ = columns;
    rows_ = rows;
}

void VegetationBuffers::draw(Mirroring mirroring) const {
    size_t count = this->count(mirroring);
    if (count == 0 || atlas_ == 0) return;
    size_t first = mirroring == Mirroring::Direct ? 0 : directCount_;
    glActiveTexture(GL_TEXTURE0 + kUnitPlantAtlas);
    glBindTexture(GL_TEXTURE_2D, atlas_);
    glBindSampler(kUnitPlantAtlas, atlasSampler_.name());
    glBindVertexArray(vertexArray_.name());
    glBindBuffer(GL_ARRAY_BUFFER, instances_.name());
    const GLsizei stride = sizeof(PlantDrawInstance);
    auto at = [&](size_t member) { return (const void*)(first * sizeof(PlantDrawInstance) + member); };
    glVertexAttribPointer(kBaseSizeAttribute, 4, GL_FLOAT, GL_FALSE, stride, at(offsetof(PlantDrawInstance, baseSize)));
    glVertexAttribPointer(kTintPhaseAttribute, 4, GL_FLOAT, GL_FALSE, stride, at(offsetof(PlantDrawInstance, tintPhase)));
    glVertexAttribPointer(kVariantAttribute, 1, GL_FLOAT, GL_FALSE, stride, at(offsetof(PlantDrawInstance, variant)));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(count));
    glBindVertexArray(0);
    glBindSampler(kUnitPlantAtlas, 0);
}

}  // namespace oasis
