// Reading the shading oracle's inputs back from the driver, and decoding a surface on the CPU
// (check/oracle_inputs.h).
#include "check/oracle_inputs.h"

#include <cmath>
#include <memory>

#include "common/shared_constants.glsl"
#include "frame/frame_readback.h"
#include "frame/renderer.h"
#include "passes/pass.h"
#include "render/pixel_readback.h"
#include "render/texture_units.h"

namespace oasis {
namespace {

std::vector<float> readColourTarget(const FrameTargets& targets, Target target) {
    requireHeldAfterFrame(targets, target);
    std::vector<float> pixels(size_t(targets.width()) * size_t(targets.height()) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.framebuffer({target}));
    readColourFloats(targets.width(), targets.height(), pixels.data());
    return pixels;
}

// The surfaces' texels: the G-buffer a deferred frame lit; for a forward frame, which stores none,
// the frame's surface shaders drawn again into float targets (FrameViews::fillExactSurfaces, the
// probe's way): the same Surface values its fragments shaded, unrounded.
void readSurfaces(Renderer& renderer, OracleInputs& in) {
    const FrameTargets& frame = renderer.targets();
    std::unique_ptr<FrameTargets> exact;
    if (in.forward) {
        exact = std::make_unique<FrameTargets>(*findGBufferLayout("full"), frame.depth(), frame.width(), frame.height(),
                                               "shading oracle: forward surfaces");
        renderer.views().fillExactSurfaces(*exact, WaterScene::Direct);
    }
    const FrameTargets& surfaces = exact ? *exact : frame;
    // The table's row, not the targets' copy: a forward frame's `exact` targets end with this function.
    in.layout = findGBufferLayout(surfaces.layout().name);
    in.compact = surfaces.layout().positionFromDepth();
    in.albedo = readColourTarget(surfaces, Target::Albedo);
    in.normal = readColourTarget(surfaces, Target::Normal);
    in.info = readColourTarget(surfaces, Target::Info);
    if (surfaces.layout().stores(Target::Position)) in.position = readColourTarget(surfaces, Target::Position);
    in.source = in.forward ? "surfaces: the forward surface shaders drawn again into float targets (as probe --shading)"
                           : std::string("surfaces: the ") + surfaces.layout().name + " G-buffer's texels, decoded on the CPU";
}

// One layer's depths drawn into a float target and read back, where the context cannot read depth
// (OpenGL ES without GL_NV_read_depth_stencil): texelFetch of the stored float, compare mode off.
void drawShadowLayer(Renderer& renderer, int layer, float* out) {
    const ShadowMaps& maps = renderer.parts().shadowMaps;
    const int size = maps.mapSize();
    gl::Texture colour = gl::createTargetTexture("shading oracle: a shadow map layer", GL_R32F, size, size);
    gl::Framebuffer framebuffer = gl::createFramebuffer("shading oracle: a shadow map layer");
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.name());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour.name(), 0);
    GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &drawBuffer);
    glViewport(0, 0, size, size);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    maps.bind();
    glActiveTexture(GL_TEXTURE0 + kUnitShadowMap);  // the parameters are the bound array's
    // Compare mode off for texelFetch of the stored depth. OpenGL ES 3.0 then calls a depth texture
    // with linear filtering incomplete (fetches return 0: every pixel shadowed), which WebGL 2 on
    // SwiftShader enforces and Mesa does not: nearest filtering for the read too.
    GLint minFilter = 0, magFilter = 0;
    glGetTexParameteriv(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, &minFilter);
    glGetTexParameteriv(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, &magFilter);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    GLuint program = renderer.parts().shaders.program("readback.shadow-layer");
    glUseProgram(program);
    glUniform1i(glGetUniformLocation(program, "shadowLayer"), layer);
    renderer.parts().geometry.drawFullscreenTriangle();
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, minFilter);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, magFilter);
    glActiveTexture(GL_TEXTURE0);
    std::vector<float> rgba(size_t(size) * size_t(size) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.name());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, size, size, GL_RGBA, GL_FLOAT, rgba.data());
    for (size_t i = 0; i < size_t(size) * size_t(size); ++i) out[i] = rgba[4 * i];
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// The cascades' depths, layer by layer, where the frame drew them: read by glReadPixels where the
// context reads depth, else drawn out.
void readShadowMaps(Renderer& renderer, OracleInputs& in) {
    if (in.frame.shadow.x == 0.0f) return;
    const bool drawn = !renderer.paths().capabilities.depthStencilRead.available;
    const ShadowMaps& maps = renderer.parts().shadowMaps;
    ShadowMapDepths& out = in.shadowMaps;
    out.size = maps.mapSize();
    out.layers = maps.layers();
    out.depths.resize(size_t(out.size) * size_t(out.size) * size_t(out.layers));
    while (glGetError() != GL_NO_ERROR) {
    }
    for (int layer = 0; layer < out.layers; ++layer) {
        float* depths = out.depths.data() + size_t(layer) * size_t(out.size) * size_t(out.size);
        if (drawn) {
            drawShadowLayer(renderer, layer, depths);
            continue;
        }
        glBindFramebuffer(GL_READ_FRAMEBUFFER, maps.framebuffer(layer));
        glReadPixels(0, 0, out.size, out.size, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
    }
    if (GLenum error = glGetError(); error != GL_NO_ERROR) {
        in.shadowMapsUnreadable = "reading the 32-bit float shadow maps failed (GL error " + std::to_string(error) + ")";
        out = ShadowMapDepths();
        return;
    }
    in.shadowMapsHow = drawn ? "drawn out (this context cannot read depth back)" : "read back";
}

glm::dvec4 texel(const std::vector<float>& values, const OracleInputs& in, int x, int y) {
    const float* v = &values[(size_t(y) * size_t(in.width) + size_t(x)) * 4];
    return glm::dvec4(v[0], v[1], v[2], v[3]);
}

// common/depth.glsl: window depth to the camera-relative point under the pixel's centre.
glm::dvec3 positionFromDepth(const OracleInputs& in, int x, int y, double depth) {
    const FrameData& f = in.frame;
    double nearPlane = f.depthRange.x, farPlane = f.depthRange.y, eyeDepth;
    if (in.depthReversed) {
        eyeDepth = nearPlane * farPlane / (depth * (farPlane - nearPlane) + nearPlane);
    } else {
        double ndc = depth * 2.0 - 1.0;
        eyeDepth = 2.0 * nearPlane * farPlane / (farPlane + nearPlane - ndc * (farPlane - nearPlane));
    }
    glm::dvec2 screenUv((x + 0.5) / in.width, (y + 0.5) / in.height);
    glm::dvec4 onNearPlane = glm::dmat4(f.inverseViewProjection) *
                             glm::dvec4(screenUv * 2.0 - 1.0, double(f.depthConvention.y), 1.0);
    return glm::dvec3(onNearPlane) / onNearPlane.w * (eyeDepth / nearPlane);
}

}  // namespace

OracleInputs readOracleInputs(Renderer& renderer) {
    OracleInputs in;
    in.width = renderer.targets().width();
    in.height = renderer.targets().height();
    in.forward = renderer.pipeline() == PipelineKind::Forward;
    in.lightVolumes = !in.forward && renderer.lastFrame().setup.lightMethod == LightMethod::Volumes;
    in.radiance = readTarget(renderer, Target::Radiance);
    in.depth = readDepth(renderer);
    in.stencil = readStencil(renderer);
    in.frame = readFrameBlock(renderer);
    in.lights = readLightList(renderer);
    in.depthReversed = in.frame.depthConvention.x != 0.0f;  // common/depth.glsl's depthReversed()
    readShadowMaps(renderer, in);
    readSurfaces(renderer, in);
    in.source += "; depth, stencil and Radiance (RGBA16F) of the frame; the frame's uniform block and light list read back "
                 "from their buffers";
    in.source += in.frame.shadow.x == 0.0f ? "; no shadow maps this frame"
                 : in.shadowMapsUnreadable.empty() ? "; the shadow maps' depths " + in.shadowMapsHow
                                                   : "; the shadow maps unreadable (" + in.shadowMapsUnreadable + ")";
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return in;
}

std::vector<Resource> oracleReads(const GBufferLayout& layout) {
    std::vector<Resource> reads = {Target::DepthStencil, Target::Radiance, Target::Reflection, Buffer::ShadowMaps,
                                   Buffer::LightList};
    for (Target surface : kGBufferColourTargets)
        if (layout.stores(surface)) reads.push_back(surface);
    return reads;
}

double oracleRebuiltPositionError(const OracleInputs& in, int x, int y) {
    if (!in.compact) return 0.0;
    // A float rounding is 2^-24 of its result; the reconstruction takes a dozen of them (the depth's
    // conversion, the inverse matrix's products and sums, the division and scale): 2^-20 for them
    // all. In the standard convention what comes before the cancellation (f + n, ndc (f - n) and
    // the depth's own conversion, each 2^-24 at most) grows by its gain, (f + n + |ndc| (f - n))
    // over what is left: 2^-23 of that bounds the three together.
    constexpr double kRoundings = 1.0 / 1048576.0, kCancelled = 1.0 / 8388608.0;
    if (in.depthReversed) return kRoundings;
    double nearPlane = in.frame.depthRange.x, farPlane = in.frame.depthRange.y;
    double ndc = double(in.depth[size_t(y) * size_t(in.width) + size_t(x)]) * 2.0 - 1.0;
    double terms = farPlane + nearPlane + std::fabs(ndc) * (farPlane - nearPlane);
    return kRoundings + kCancelled * terms / std::fabs(farPlane + nearPlane - ndc * (farPlane - nearPlane));
}

bool oracleWaterAt(const OracleInputs& in, int x, int y) {
    return (in.stencil[size_t(y) * size_t(in.width) + size_t(x)] & 0x7f) == kStencilWater;
}

bool oracleSurfaceAt(const OracleInputs& in, int x, int y, OracleSurface& s) {
    GBufferLayout::StoredSurface stored =
        in.layout->storedSurface(texel(in.albedo, in, x, y), texel(in.normal, in, x, y), texel(in.info, in, x, y));
    double depth = in.depth[size_t(y) * size_t(in.width) + size_t(x)];
    // gbufferSkyAt: a layout that rebuilds positions from depth tells the sky by its depth alone.
    bool sky = in.compact ? (in.depthReversed ? depth <= 0.0 : depth >= 1.0) : (stored.flags & OASIS_SURFACE_SKY) != 0u;
    if (sky) return false;
    s.albedo = stored.albedo;
    s.normal = stored.normal;
    s.relativePosition = in.compact ? positionFromDepth(in, x, y, depth) : glm::dvec3(texel(in.position, in, x, y));
    s.specularPower = stored.specularPower;
    s.specularIntensity = stored.specularIntensity;
    s.flags = stored.flags;
    return true;
}

}  // namespace oasis
