// Uploads the terrain grid; draws it and full-screen triangles.
#include "render/scene_geometry.h"

#include <algorithm>

#include "scene/point_lights.h"

namespace oasis {

SceneGeometry::SceneGeometry(const TerrainGridDensity& density) : density_(density) {
    GridMesh mesh = buildTerrainGrid(density);
    indexCount_ = int(mesh.indices.size());
    terrainVao_ = gl::createVertexArray("terrain grid");
    terrainVertices_ = gl::createBuffer("terrain grid vertices");
    terrainIndices_ = gl::createBuffer("terrain grid indices");
    glBindVertexArray(terrainVao_.name());
    glBindBuffer(GL_ARRAY_BUFFER, terrainVertices_.name());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(glm::vec2)), mesh.vertices.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(glm::vec2), nullptr);
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

void SceneGeometry::drawWaterQuad() const {
    glBindVertexArray(emptyVao_.name());
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glBindVertexArray(0);
}

void SceneGeometry::drawFullscreenTriangle() const {
    glBindVertexArray(emptyVao_.name());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

}  // namespace oasis
