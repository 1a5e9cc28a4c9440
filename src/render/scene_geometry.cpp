// Uploads the terrain grid; computes its heights once a frame; draws it and full-screen triangles.
#include "render/scene_geometry.h"

#include <algorithm>

#include "common/shared_constants.glsl"
#include "scene/point_lights.h"

namespace oasis {

SceneGeometry::SceneGeometry(const TerrainGridDensity& density) : density_(density) {
    GridMesh mesh = buildTerrainGrid(density);
    indexCount_ = int(mesh.indices.size());
    gridVertexCount_ = int(mesh.vertices.size());
    // The grid's coordinates, read only where the heights are computed.
    terrainGridVao_ = gl::createVertexArray("terrain grid coordinates (heights pass)");
    terrainVertices_ = gl::createBuffer("terrain grid vertices");
    glBindVertexArray(terrainGridVao_.name());
    glBindBuffer(GL_ARRAY_BUFFER, terrainVertices_.name());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(glm::vec2)), mesh.vertices.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(glm::vec2), nullptr);
    // The heights the terrain is drawn with: the grid vertices in the same order, written by the
    // transform feedback (offset xz, then height and its gradient), read as attributes 1 and 2.
    terrainHeights_ = gl::createBuffer("terrain grid heights (this frame's)");
    glBindBuffer(GL_ARRAY_BUFFER, terrainHeights_.name());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(size_t(gridVertexCount_) * kHeightsStride), nullptr, GL_DYNAMIC_COPY);
    // A draw needs a complete framebuffer even when it rasterises nothing, and a headless context
    // has none bound by default: a 1x1 one of its own.
    heightsTargetTexture_ = gl::createTargetTexture("terrain heights pass: 1x1 target (nothing drawn)", GL_R8, 1, 1);
    heightsTarget_ = gl::createFramebuffer("terrain heights pass: 1x1 target (nothing drawn)");
    glBindFramebuffer(GL_FRAMEBUFFER, heightsTarget_.name());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, heightsTargetTexture_.name(), 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    terrainVao_ = gl::createVertexArray("terrain grid");
    terrainIndices_ = gl::createBuffer("terrain grid indices");
    glBindVertexArray(terrainVao_.name());
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, kHeightsStride, nullptr);
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, kHeightsStride, reinterpret_cast<const void*>(2 * sizeof(float)));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, terrainIndices_.name());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(uint32_t)), mesh.indices.data(),
                 GL_STATIC_DRAW);
    glBindVertexArray(0);
    emptyVao_ = gl::createVertexArray("full-screen triangle (no attributes)");

    std::vector<glm::vec3> sphere = lightVolumeMesh();
    lightVolumeVertexCount_ = int(sphere.size());
    lightVolumeVao_ = gl::createVertexArray("light volume sphere");
    lightVolumeVertices_ = gl::createBuffer("light volume sphere vertices");
    glBindVertexArray(lightVolumeVao_.name());
    glBindBuffer(GL_ARRAY_BUFFER, lightVolumeVertices_.name());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(sphere.size() * sizeof(glm::vec3)), sphere.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindVertexArray(0);
}

void SceneGeometry::computeTerrainHeights() const {
    GLint previousTarget = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousTarget);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, heightsTarget_.name());
    glEnable(GL_RASTERIZER_DISCARD);
    glBindVertexArray(terrainGridVao_.name());
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, terrainHeights_.name());
    glBeginTransformFeedback(GL_POINTS);
    glDrawArrays(GL_POINTS, 0, gridVertexCount_);
    glEndTransformFeedback();
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    glBindVertexArray(0);
    glDisable(GL_RASTERIZER_DISCARD);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previousTarget));
}

void SceneGeometry::drawTerrain() const {
    glBindVertexArray(terrainVao_.name());
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

void SceneGeometry::drawTerrainStrips(int first, int end) const {
    const int perStrip = density_.segments * 6;  // two triangles per segment (buildTerrainGrid)
    first = std::max(first, 0);
    end = std::min(end, density_.rings);
    if (end <= first) return;
    glBindVertexArray(terrainVao_.name());
    glDrawElements(GL_TRIANGLES, (end - first) * perStrip, GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(size_t(first) * size_t(perStrip) * sizeof(uint32_t)));
    glBindVertexArray(0);
}

void SceneGeometry::drawWaterGrid() const {
    glBindVertexArray(emptyVao_.name());
    glDrawArrays(GL_TRIANGLES, 0, 6 * OASIS_WATER_GRID_CELLS * OASIS_WATER_GRID_CELLS);
    glBindVertexArray(0);
}

void SceneGeometry::drawFullscreenTriangle() const {
    glBindVertexArray(emptyVao_.name());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

}  // namespace oasis
