// The sun's cascaded shadow maps: each cascade's depth from the sun, casters drawn with depth
// clamping (a caster nearer the sun than the cascade's box still shadows it) and a slope-scaled
// depth offset (the receiver's offsets in common/shadows.glsl do the rest against acne).
#include "passes/shadow_pass.h"

#include <cmath>
#include <utility>

#include "render/shadow_maps.h"

namespace oasis {
namespace {

// glPolygonOffset: depth slope factor and units. A plant billboard seen edge-on by the sun has a
// steep slope; the factor keeps its own texels from shadowing it.
constexpr float kSlopeFactor = 2.0f;
constexpr float kUnits = 2.0f;

// The grid's strips whose ground lies between the horizontal distances `reach` (x nearest, y
// farthest) from the camera: ring i >= 1 at firstRadius * ratio^(i - 1), ring 0 the centre
// (common terrain.vert). A strip's straight edges come nearer than its inner ring by at most
// 1 - cos(half a segment), under 0.1% for 128 segments over a full circle: 1% of slack covers it.
std::pair<int, int> stripsWithin(glm::vec2 reach, const TerrainWedge& wedge, const TerrainGridDensity& grid) {
    auto ringRadius = [&](int ring) {
        return ring == 0 ? 0.0f : grid.firstRingRadius * std::pow(wedge.ringRatio, float(ring - 1));
    };
    int first = 0, end = grid.rings;
    while (first < grid.rings && ringRadius(first + 1) < reach.x * 0.99f) ++first;
    while (end > first && ringRadius(end - 1) * 0.99f > reach.y) --end;
    return {first, end};
}

}  // namespace

void ShadowPass::execute(PassContext& context) {
    ShadowMaps& maps = *context.shadowMaps;
    const FrameSetup& frame = context.frame;
    const ShadowCascades& cascades = frame.shadowCascades;
    maps.ensure(frame.shadowQuality->mapSize, cascades.count);
    // The cascades' matrices map depth to -1..1: draw with OpenGL's default clip depth whatever the
    // frame's convention (reversed-z frames set 0..1 for the whole frame).
    bool reversed = frame.view.depthMapping == DepthMapping::Reversed;
    if (reversed) glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);  // the sun sees the terrain's and the billboards' either side
    if (maps.depthClamp()) glEnable(GL_DEPTH_CLAMP);  // else common/shadow_caster.glsl flattens the casters
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(kSlopeFactor, kUnits);
    glViewport(0, 0, maps.mapSize(), maps.mapSize());

    GLuint terrain = context.shaders.program("terrain.shadow");
    GLint terrainCascade = glGetUniformLocation(terrain, "shadowCascade");
    bool plants = frame.vegetationEnabled && context.vegetation.hasAtlas() &&
                  context.vegetation.count(Mirroring::Direct) > 0;
    GLuint vegetation = plants ? context.shaders.program("vegetation.shadow") : 0;
    GLint vegetationCascade = plants ? glGetUniformLocation(vegetation, "shadowCascade") : -1;
    const GLfloat farthest = 1.0f;
    for (int c = 0; c < cascades.count; ++c) {
        glBindFramebuffer(GL_FRAMEBUFFER, maps.framebuffer(c));
        glClearBufferfv(GL_DEPTH, 0, &farthest);
        glUseProgram(terrain);
        glUniform1i(terrainCascade, c);
        // Only the rings that can cast into this cascade's box (most of a low cascade's are not).
        auto [firstStrip, endStrip] = stripsWithin(cascades.casterReach[size_t(c)], frame.wedge,
                                                   context.geometry.density());
        context.geometry.drawTerrainStrips(firstStrip, endStrip);
        if (plants) {
            glUseProgram(vegetation);
            glUniform1i(vegetationCascade, c);
            context.vegetation.draw(Mirroring::Direct);
        }
    }

    glDisable(GL_POLYGON_OFFSET_FILL);
    if (maps.depthClamp()) glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_DEPTH_TEST);
    if (reversed) glClipControl(context.targets.depth().clipOrigin, context.targets.depth().clipDepthMode);
    maps.bind();
}

}  // namespace oasis
