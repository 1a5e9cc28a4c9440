// The renderer's choices from what the context offers (frame/renderer.h, frame/render_paths.h):
// the depth convention, the G-buffer layout, the lights' path, the water's bounds and the light
// method, each with the reason it was made.
#include "frame/renderer.h"

#include <epoxy/gl.h>

#include <memory>
#include <string>

namespace oasis {

void Renderer::setCapabilities(const RendererCapabilities& capabilities) {
    // In the order the session gave them one by one: the light method follows the lights' path.
    RendererCapabilities& given = paths_.capabilities;
    given = capabilities;
    if (!given.ssbo.available) lights_.ssboMissingReason = given.ssbo.reason;
    paths_.lights = chooseLightsPath(given.ssbo.available, given.forcedLightsPath, lights_.ssboMissingReason);
    chooseWaterBounds();
    paths_.lightMethod = chooseLightMethod(given.compute.available, given.forcedLightMethod, given.compute.reason,
                                          paths_.lights.path);
    setDepthConvention(*requested_.depth);
    if (targets_ && requested_.layout) {
        const GBufferLayout requested = *requested_.layout;  // configure replaces the stored copy
        configure(targets_->width(), targets_->height(), requested);
    }
}

const GBufferLayout& Renderer::chooseGBufferLayout(const GBufferLayout& requested, std::string& reason) const {
    const RendererCapabilities::Feature& norm16 = paths_.capabilities.norm16Targets;
    if (!requested.needsNorm16Targets()) {
        reason = requested.name + " (asked for)";
        return requested;
    }
    if (norm16.available) {
        reason = requested.name + " (asked for; " + norm16.reason + ")";
        return requested;
    }
    const GBufferLayout& fallback = norm16FallbackGBufferLayout();
    reason = fallback.name + " (" + requested.name + " was asked for but its 16-bit unorm target is not " +
             "colour-renderable: " + norm16.reason + ")";
    return fallback;
}

void Renderer::setDepthConvention(const DepthConvention& requested) {
    const DepthConvention* use = &requested;
    std::string reason;
    if (!requested.needsClipControl())
        reason = requested.name + " (OpenGL's default clip control)";
    else if (paths_.capabilities.clipControl.available)
        reason = requested.name + " (" + paths_.capabilities.clipControl.reason + ")";
    else {
        use = &standardDepthConvention();
        reason = use->name + " (" + requested.name + " was asked for but " + paths_.capabilities.clipControl.reason + ")";
    }
    if (use != paths_.depth && targets_) {
        // Built before anything changes: a failed allocation throws and keeps the old targets,
        // convention and reason.
        targets_ = std::make_unique<FrameTargets>(targets_->layout(), *use, targets_->width(), targets_->height());
        forgetGBuffer();
    }
    requested_.depth = &requested;
    paths_.depthReason = std::move(reason);
    paths_.depth = use;
    paths_.depthFellBack = use != &requested;
}

void Renderer::chooseWaterBounds() {
    const bool ssbo = paths_.capabilities.ssbo.available;
    GLint vertexBlocks = 0, fragmentBlocks = 0, clipDistances = 0;
    if (ssbo) {
        glGetIntegerv(GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS, &vertexBlocks);
        glGetIntegerv(GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS, &fragmentBlocks);
    }
    glGetIntegerv(GL_MAX_CLIP_DISTANCES, &clipDistances);
    // GLSL 4.30's own storage blocks, atomics on them and early fragment tests: the extensions that
    // bring them to older GLSL (softpipe's 3.30) are not worth a second spelling of the shader.
    const bool glsl430 = epoxy_gl_version() >= 43;
    paths_.waterBoundsAvailable = ssbo && glsl430 && vertexBlocks >= 1 && fragmentBlocks >= 1 && clipDistances >= 5;
    if (paths_.waterBoundsAvailable)
        paths_.waterBoundsReason = "bounded to the visible water (recorded in a storage block, clipped with 4 clip distances; "
                             "skipped where no water is seen: the water mask's occlusion query, conditional rendering)";
    else if (!ssbo)
        paths_.waterBoundsReason = "whole screen, stencil-masked (no storage blocks: " + lights_.ssboMissingReason + ")";
    else if (!epoxy_is_desktop_gl())
        paths_.waterBoundsReason = "whole screen, stencil-masked (not on OpenGL ES yet: the bounds' storage block is "
                             "bound by name, which ES cannot do)";
    else if (!glsl430)
        paths_.waterBoundsReason = "whole screen, stencil-masked (needs GL 4.3: storage blocks, their atomics and early "
                             "fragment tests in GLSL 4.30; this context is " + std::to_string(epoxy_gl_version() / 10) +
                             "." + std::to_string(epoxy_gl_version() % 10) + ")";
    else
        paths_.waterBoundsReason = "whole screen, stencil-masked (storage blocks in vertex/fragment shaders " +
                             std::to_string(vertexBlocks) + "/" + std::to_string(fragmentBlocks) +
                             ", clip distances " + std::to_string(clipDistances) + "; need 1/1 and 5)";
    if (paths_.waterBoundsAvailable && !water_.bounds.name()) {
        water_.bounds = gl::createBuffer("visible water rectangle");
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, water_.bounds.name());
        glBufferData(GL_SHADER_STORAGE_BUFFER, 4 * sizeof(GLint), nullptr, GL_DYNAMIC_DRAW);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
        water_.seen = gl::createQuery(GL_ANY_SAMPLES_PASSED, "water seen (water mask's samples)");
    }
    std::vector<std::string> defines = {"LIGHTS_UBO_CAPACITY " + std::to_string(paths_.uboLights.capacity),
                                        "LIGHTS_UBO_BLOCKS " + std::to_string(paths_.uboLights.blocks)};
    if (paths_.waterBoundsAvailable) defines.push_back("WATER_BOUNDS 1");
    // The driver workarounds that live in shaders (OASIS_ARRAY_WRITE_BY_LOOP): a #define each.
    for (const std::string& define : paths_.capabilities.workarounds.defines()) defines.push_back(define);
    if (defines != shaders_.contextDefines()) shaders_.setContextDefines(defines);
}

}  // namespace oasis
