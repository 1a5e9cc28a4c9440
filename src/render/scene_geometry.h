// GPU-side scene data built once and shared by both pipelines: the terrain grid's buffers (its
// heights rewritten each frame) and an empty vertex array for full-screen triangles. Switching
// pipelines never rebuilds it.
#pragma once
#include "gl/objects.h"
#include "scene/terrain.h"

namespace oasis {

class SceneGeometry {
public:
    explicit SceneGeometry(const TerrainGridDensity& density);

    const TerrainGridDensity& density() const { return density_; }
    // Writes every grid vertex's place and height for this frame's camera into the buffer the
    // terrain draws read, by transform feedback of the bound program (terrain.heights; nothing is
    // rasterised). TerrainHeightsPass calls it before any terrain is drawn in a frame.
    void computeTerrainHeights() const;
    int gridVertexCount() const { return gridVertexCount_; }
    void drawTerrain() const;
    // The grid's strips [first, end) only, strip i lying between rings i and i + 1 (the indices
    // go ring by ring, so a run of strips is one run of indices).
    void drawTerrainStrips(int first, int end) const;
    void drawFullscreenTriangle() const;
    void drawWaterGrid() const;  // vertices generated in water.vert (OASIS_WATER_GRID_CELLS)
    int terrainTriangles() const { return indexCount_ / 3; }
    // The light volume (scene/point_lights.h lightVolumeMesh): bind once, then draw per light.
    void bindLightVolume() const { glBindVertexArray(lightVolumeVao_.name()); }
    void drawBoundLightVolume() const { glDrawArrays(GL_TRIANGLES, 0, lightVolumeVertexCount_); }

private:
    TerrainGridDensity density_;
    // terrain.vert's heightsOffset (vec2) and heightsHeight (vec3), interleaved.
    static constexpr GLsizei kHeightsStride = 5 * sizeof(float);
    gl::VertexArray terrainVao_, terrainGridVao_, emptyVao_;
    gl::Buffer terrainVertices_, terrainHeights_, terrainIndices_;
    gl::Texture heightsTargetTexture_;
    gl::Framebuffer heightsTarget_;
    int indexCount_ = 0;
    int gridVertexCount_ = 0;
    gl::VertexArray lightVolumeVao_;
    gl::Buffer lightVolumeVertices_;
    int lightVolumeVertexCount_ = 0;
};

}  // namespace oasis
