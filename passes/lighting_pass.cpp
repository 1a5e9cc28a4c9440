// One full-screen triangle at the far plane; every pixel's surface comes from the G-buffer. Where
// the depth-stencil target can be attached, the depth test keeps the triangle to the surfaces
// (SkyPass draws the rest): llvmpipe runs both sides of a shader's branches, so a sky branch here
// cost every pixel the sky's noise as well as the sun's shading. With the tiled light method the
// variant also adds the lights its LightTilingPass listed for the pixel's tile.
#include "passes/lighting_pass.h"

namespace oasis {

DepthRead LightingPass::depthRead(const FrameSetup& frame) const {
    return mirroring_ == Mirroring::Direct && lightingSamplesDepthTarget(frame) ? DepthRead::FromTarget
                                                                               : DepthRead::FromCopy;
}

bool LightingPass::testsSurfaces(const FrameSetup& frame) const {
    // A read of the very target it would test is allowed only where the context has read-only depth.
    return depthRead(frame) == DepthRead::FromCopy || frame.readOnlyDepth;
}

// Whether the tiled variant adds the point lights: the tiled method, lights to add (LightTilingPass
// of the same half writes the list; the frame graph keeps it because this reads it).
static bool addsTiledLights(const FrameSetup& frame) {
    return frame.lightMethod == LightMethod::Tiled && !frame.lights.empty();
}

std::vector<Access> LightingPass::declaredAccesses(const FrameSetup& frame) const {
    std::vector<Access> used = gbufferSamples(frame, depthRead(frame));
    for (Target target : surfaceOutputTargets(frame, SurfaceOutput::Forward, mirroring_))
        used.push_back({target, Use::Write});
    // Tested, never written; mirrored, the stencil keeps it inside the water.
    if (testsSurfaces(frame)) appendDepthStencil(used, {Use::DepthTest});
    if (mirroring_ == Mirroring::Mirrored) appendDepthStencil(used, {Use::StencilTest});
    if (addsTiledLights(frame)) {
        used.push_back({Buffer::LightTiles, Use::Sample});
        used.push_back({Buffer::LightList, Use::Sample});
    }
    if (frame.shadowsActive) used.push_back({Buffer::ShadowMaps, Use::Sample});
    return used;
}

void LightingPass::execute(PassContext& context) {
    bool fused = toneMapFusedInto(context.frame, SurfaceOutput::Forward, mirroring_);
    bool mirrored = mirroring_ == Mirroring::Mirrored;
    // Radiance (or Reflection), with the depth-stencil target where it tests the surfaces; else
    // every pixel, the sky's left black for SkyPass to draw over.
    bindDeclaredOutputs(context);
    if (testsSurfaces(context.frame)) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(context.targets.depth().fartherFunc);
        glDepthMask(GL_FALSE);
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    beginMirroredDraw(mirroring_);
    if (mirrored) beginWaterBoundedDraw(context);
    std::string program = mirrored ? "lighting.mirrored" : fused ? "lighting.tonemapped" : "lighting";
    if (addsTiledLights(context.frame)) program += ".tiled";
    glUseProgram(context.shaders.program(context.targets.layout().program(program)));
    context.geometry.drawFullscreenTriangle();
    if (mirrored) endWaterBoundedDraw(context);
    endMirroredDraw(mirroring_);
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace oasis
