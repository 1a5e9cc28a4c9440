// Stencil light volumes. Marking: both faces drawn with depth test LESS (GREATER with reversed
// depth: in front of the surface, either way) and no writes but the stencil bit, INVERT on depth fail. A surface inside the volume is in front of its back face
// (one toggle) and behind its front face (none); in front of both is two toggles, behind both
// none. With the camera inside, or the front face cut by the near plane, the back face alone
// toggles, so there are no holes; depth clamping keeps back faces beyond the far plane (where the
// context has none, a volume crossing the far plane lights only its nearer part). Shading:
// the back faces, no depth test, where the bit is set, added; the pass resets the bit (ZERO).
#include "passes/light_volume_pass.h"

#include "render/light_paths.h"

namespace oasis {
namespace {

// Whether a sphere (camera-relative centre) can touch the view frustum: the six clip planes of
// the frame's view (scene/camera.h), normalised; a sphere wholly outside one plane is skipped.
bool sphereInFrustum(const glm::mat4& viewProjection, DepthMapping mapping, glm::vec3 centre, float radius) {
    for (const glm::vec4& plane : frustumPlanes(viewProjection, mapping)) {
        float length = glm::length(glm::vec3(plane));
        if (glm::dot(glm::vec3(plane), centre) + plane.w < -radius * length) return false;
    }
    return true;
}

}  // namespace

void LightVolumePass::execute(PassContext& context) {
    const FrameTargets& targets = context.targets;
    bool mirrored = mirroring_ == Mirroring::Mirrored;
    bindDeclaredOutputs(context);
    std::string suffix = (mirrored ? ".mirrored" : "") + lightsVariantSuffix(context.frame.lightsPath);
    GLuint mark = context.shaders.program("light.mark" + suffix);
    GLuint shade = context.shaders.program(targets.layout().program("light.shade" + suffix));
    GLint markIndex = glGetUniformLocation(mark, "lightIndex");
    GLint shadeIndex = glGetUniformLocation(shade, "lightIndex");

    // Mirrored: only water pixels (the low bits) are touched; direct: every pixel.
    const GLint surfaceRef = mirrored ? kStencilWater : 0, surfaceMask = mirrored ? 0x7F : 0x00;
    glEnable(GL_STENCIL_TEST);
    glStencilMask(kStencilLightVolumeBit);
    if (context.depthClamp) glEnable(GL_DEPTH_CLAMP);
    glDepthMask(GL_FALSE);
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CCW);  // only the centre is mirrored: the sphere keeps its winding
    glBlendFunc(GL_ONE, GL_ONE);
    context.geometry.bindLightVolume();
    const FrameData& frame = context.frame.data;
    for (int i = 0; i < int(context.frame.lights.size()); ++i) {
        glm::vec4 sphere = context.frame.lights[size_t(i)].positionRadius;
        if (mirrored) sphere.y = 2.0f * (frame.water.x - frame.cameraPosition.y) - sphere.y;  // as light_volume.vert
        // Wholly outside one of the frustum's planes: no surface in view lies inside the sphere.
        if (!sphereInFrustum(frame.viewProjection, context.frame.view.depthMapping, glm::vec3(sphere), sphere.w * 1.01f)) continue;
        // 1. Mark: no colour, both faces, invert the bit where the depth test fails.
        glUseProgram(mark);
        glUniform1i(markIndex, i);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDisable(GL_CULL_FACE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(targets.depth().nearerFunc);
        glStencilFunc(GL_EQUAL, surfaceRef, surfaceMask);
        glStencilOp(GL_KEEP, GL_INVERT, GL_KEEP);
        context.geometry.drawBoundLightVolume();
        // 2. Shade: back faces where the bit is set, added; reset the bit as each pixel is shaded.
        glUseProgram(shade);
        glUniform1i(shadeIndex, i);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT);
        glDisable(GL_DEPTH_TEST);
        glEnable(GL_BLEND);
        glStencilFunc(GL_EQUAL, kStencilLightVolumeBit | surfaceRef, kStencilLightVolumeBit | surfaceMask);
        glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);
        context.geometry.drawBoundLightVolume();
        glDisable(GL_BLEND);
    }
    glBindVertexArray(0);
    glCullFace(GL_BACK);
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
    glDepthFunc(targets.depth().nearerFunc);
    if (context.depthClamp) glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace oasis
