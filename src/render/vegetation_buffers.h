// The vegetation's GPU side: the frame's billboard instances (both draw lists of
// scene/vegetation.h in one stream buffer), the vertex array that reads them, and the sampler
// that reads the plant atlas with mipmaps. Draws work on GL 3.3: a list is selected by pointing
// the instanced attributes at its first instance, not by base-instance draws (GL 4.2).
#pragma once
#include "gl/objects.h"
#include "render/surface_output.h"
#include "scene/vegetation.h"

namespace oasis {

class VegetationBuffers {
public:
    VegetationBuffers();

    // Replaces the instances (orphaning the old storage, so a frame in flight keeps its own).
    void upload(const VegetationDrawList& list);
    // The atlas the billboards sample (0: nothing is drawn) and its grid of cells.
    void setAtlas(GLuint texture, int columns, int rows);
    bool hasAtlas() const { return atlas_ != 0; }
    // Binds the atlas and its sampler to the plant-atlas unit and draws one list as 4-vertex strips.
    void draw(Mirroring mirroring) const;
    size_t count(Mirroring mirroring) const { return mirroring == Mirroring::Direct ? directCount_ : mirroredCount_; }
    // The instances of both lists (direct first), PlantDrawInstance each: the frame's PlantInstances.
    GLuint instanceBuffer() const { return instances_.name(); }
    int atlasColumns() const { return columns_; }
    int atlasRows() const { return rows_; }

private:
    gl::VertexArray vertexArray_;
    gl::Buffer instances_;
    gl::Sampler atlasSampler_;
    GLuint atlas_ = 0;
    int columns_ = 1, rows_ = 1;
    size_t directCount_ = 0, mirroredCount_ = 0;
};

}  // namespace oasis
