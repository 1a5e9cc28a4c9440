// What the renderer is given by the context (RendererCapabilities, once, whole) and the paths it
// chose from it (RenderPaths, read through Renderer::paths()), each choice with its reason.
#pragma once
#include <optional>
#include <string>

#include "gl/driver_workarounds.h"
#include "render/depth_convention.h"
#include "render/gbuffer_layout.h"
#include "render/light_method.h"
#include "render/light_paths.h"

namespace oasis {

// What the context offers the renderer, measured once (with --force applied) and given to each
// renderer whole (Renderer::setCapabilities): whether it has it and, where not, why; and the path
// and method the options force.
struct RendererCapabilities {
    struct Feature {
        bool available = false;
        std::string reason;
    };
    Feature ssbo, compute, clipControl, readOnlyDepth;
    Feature depthStencilRead;  // glReadPixels of depth and stencil, else they are drawn out to be read
    // 16-bit unorm colour targets (the compact layout's RG16 normal): desktop GL; ES only with
    // EXT_texture_norm16 (gl::Capabilities::norm16TargetsAvailable).
    Feature norm16Targets;
    std::optional<LightsPath> forcedLightsPath;
    std::optional<LightMethod> forcedLightMethod;
    // The driver workarounds in effect (gl/driver_workarounds.h): the table's default for this
    // context's GL_RENDERER until a session gives the set its request resolved to.
    gl::WorkaroundSet workarounds;
};

// The renderer's capabilities and its choices from them and the scene: those of the last frame
// (of construction or setCapabilities before any frame). capabilities.readOnlyDepth says whether
// the compact lighting that samples depth in place may test against that target too.
struct RenderPaths {
    // What the renderer was last given (its own measure of the context until setCapabilities).
    RendererCapabilities capabilities;
    // The depth convention in use (render/depth_convention.h): the one asked for
    // (Renderer::setDepthConvention), or standard where reversed-z lacks glClipControl (GL 4.5 /
    // GL_ARB_clip_control); why, and whether it fell back.
    const DepthConvention* depth = &standardDepthConvention();
    std::string depthReason;
    bool depthFellBack = false;
    // The G-buffer layout in use (render/gbuffer_layout.h): the one asked for (Renderer::configure),
    // or standard where the one asked for has a 16-bit unorm target and the context cannot draw
    // into one (OpenGL ES without EXT_texture_norm16, WebGL 2 on SwiftShader); the name asked for,
    // why, and whether it fell back. Null before the first configure.
    const GBufferLayout* gbuffer = nullptr;
    std::string gbufferRequested;
    std::string gbufferReason;
    bool gbufferFellBack = false;
    // How shaders read the point lights, decided each frame from SceneSettings::lights.path (forced)
    // or else the context (SSBOs present or not); a forced SSBO path the context lacks falls back
    // to ubo.
    LightsPathChoice lights;
    UboLightLayout uboLights;
    // Whether the reflection's passes can be bounded to the visible water (storage blocks in vertex
    // and fragment shaders, five clip distances: follows the SSBOs), and why (not).
    bool waterBoundsAvailable = false;
    std::string waterBoundsReason;
    // How the deferred pipeline adds the lights (render/light_method.h), decided each frame from
    // SceneSettings::lights.method and whether compute shaders (with SSBOs) exist; tiled asked for
    // without them falls back to volumes.
    LightMethodChoice lightMethod;
    // Lights the last frame drew, and how many the UBO path had to drop (0 on the SSBO paths).
    int lightsDrawn = 0;
    int lightsDropped = 0;
};

}  // namespace oasis
