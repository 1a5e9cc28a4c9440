// What the current OpenGL context can do, measured once (version, strings, limits, extensions),
// combined with the fallbacks forced on the command line (--force). Every capability-dependent
// path choice asks this one object, so a user's driver can be reproduced by switching features off.
#pragma once
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace oasis::gl {

// Which OpenGL the context speaks (--api): desktop OpenGL core (the default) or OpenGL ES 3.x.
enum class Api { Gl, Gles };
const char* apiName(Api api);  // "gl", "gles"
bool parseApi(const std::string& text, Api& api);

// Fallbacks forced even where the driver has the feature: --force no-ssbo,no-compute,...
struct ForcedFallbacks {
    bool noSsbo = false;
    bool noCompute = false;
    bool noStencilTexturing = false;
    bool noDsa = false;
    bool noClipControl = false;  // reversed-z depth falls back to standard
    bool gl33 = false;  // create the context at OpenGL 3.3 core (the context's job, before measuring)
    bool gles30 = false;  // --api gles: treat the ES context as OpenGL ES 3.0 (core features alone)
    bool noDepthClamp = false;  // the shadow casters flattened in the shader, as on ES 3.0
    bool noReadOnlyDepth = false;  // the lighting shades every pixel instead of testing a depth it samples
    // The fallbacks a driver workaround forced rather than --force: the fallback's name -> the row's
    // (gl/driver_workarounds.h), so a reason names what really switched the feature off.
    std::map<std::string, std::string> byWorkaround;

    bool any() const {
        return noSsbo || noCompute || noStencilTexturing || noDsa || noClipControl || gl33 || gles30 || noDepthClamp ||
               noReadOnlyDepth;
    }
    std::string list() const;  // "no-ssbo,gl33" ("" when none)
    // What forced the fallback NAME: "--force no-ssbo" or "the driver workaround depth-clamp-off".
    std::string forcedBy(const std::string& name) const;
    bool has(const std::string& name) const;  // the fallback NAME is forced, by either
    // Forces the fallback NAME (a --force name) for the workaround ROW, unless already forced.
    void forceByWorkaround(const std::string& name, const std::string& row);
};
// The accepted names, for help and errors: "no-ssbo, no-compute, no-stencil-texturing, no-dsa,
// no-clip-control, gl33, gles30, no-depth-clamp, no-read-only-depth".
const char* forcedFallbackNames();
// Parses a comma-separated list into `forced` (adding to what is there); false with `error` on a bad name.
bool parseForcedFallbacks(const std::string& text, ForcedFallbacks& forced, std::string& error);

// The limits that matter to oasis (0 where the context has no such query).
struct Limits {
    int maxUniformBlockSize = 0;         // bytes: a UBO light list's ceiling
    int maxShaderStorageBlockSize = 0;   // bytes: an SSBO light list's ceiling
    int maxDrawBuffers = 0;              // the G-buffer writes 4 at once
    int maxColorAttachments = 0;
    int maxTextureSize = 0;              // the largest frame
    int maxSamples = 0;
    int maxComputeWorkGroupInvocations = 0;
    int maxComputeWorkGroupCount[3] = {0, 0, 0};
    int maxComputeWorkGroupSize[3] = {0, 0, 0};
    int maxComputeSharedMemorySize = 0;
    // Storage-block counts (measured where the driver has SSBOs): ES 3.1 guarantees only 4
    // bindings, 4 blocks per program and none in the vertex and fragment stages, fewer than
    // oasis's shaders use.
    int maxShaderStorageBufferBindings = 0;
    int maxVertexShaderStorageBlocks = 0;
    int maxFragmentShaderStorageBlocks = 0;
    int maxComputeShaderStorageBlocks = 0;
    int maxCombinedShaderStorageBlocks = 0;
};

// What oasis's storage blocks need of those limits: the bindings are shaders/common/
// shared_constants.glsl's (the light list's at 6 and 7) and the plant interpreter's 0-6; the
// blocks are those of the largest shader of each stage and program.
struct StorageNeed {
    const char* user;  // "the SSBO light list", in the reason
    int bindings;
    int vertexBlocks;
    int fragmentBlocks;
    int computeBlocks;
    int combinedBlocks;
};
extern const StorageNeed kLightListStorage;
extern const StorageNeed kPlantInterpreterStorage;
// "" when `limits` meet `need`, else the first limit below it, named, with both numbers:
// "GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS is 0, the SSBO light list needs 4".
std::string storageShortfall(const Limits& limits, const StorageNeed& need);

// One feature oasis can use: whether the driver could, whether it is used here, who limits it
// when not, and why.
struct FeatureReport {
    std::string name;    // "ssbo-light-list", "compute-plant-interpretation", ...
    bool used = false;
    std::string reason;  // "SSBOs present (GL 4.3)" / "fallback: UBO light list (no GL 4.3 / ...)"
    bool available = false;  // the driver has it, whatever --force says
    std::string limitedBy;   // "" when used, else one of the kLimitedBy* below (limitedBy())
};

// A feature's answer twice: the driver's own (--force undone: Capabilities::unforced) and the one
// oasis goes by (--force applied), with the latter's reason.
struct Availability {
    bool driver = false;
    bool tier = false;
    std::string reason;
};

// Who keeps a feature from being used, as the report words it.
constexpr const char* kLimitedByDriver = "driver";            // the driver lacks it
constexpr const char* kLimitedByForcedTier = "forced tier";   // the driver has it; a --force hides it
constexpr const char* kLimitedByNotAskedFor = "not asked for";  // oasis could; the options (or its default) do not
// "" when used, else the first of the three that holds.
std::string limitedBy(bool used, const Availability& availability);

// The context's own version and extensions, kept where a forced tier replaced them in
// Capabilities (--force gles30 on an ES 3.1+ context, --force gl33 on a driver that gave more).
struct ContextOwn {
    int major = 0, minor = 0;
    std::set<std::string> extensions;
};

struct Capabilities {
    std::string version, vendor, renderer, glslVersion;
    int major = 0, minor = 0;
    bool es = false;  // an OpenGL ES context: major.minor is the ES version
    Limits limits;
    std::set<std::string> extensions;  // every extension the context lists (the forced tier's, if one)
    ForcedFallbacks forced;
    // Set by applyForcedTier when the tier changed major.minor or extensions: what the context itself
    // gave, so that the report tells a tier's limit from the driver's.
    std::optional<ContextOwn> beforeTier;

    bool atLeast(int wantMajor, int wantMinor) const {
        return major > wantMajor || (major == wantMajor && minor >= wantMinor);
    }
    bool hasExtension(const std::string& name) const { return extensions.count(name) != 0; }

    // The driver's own answer, ignoring --force (a forced tier included): core version or extension.
    bool driverHasSsbo() const;
    bool driverHasCompute() const;
    bool driverHasStencilTexturing() const;
    bool driverHasDsa() const;
    bool driverHasDebugOutput() const;
    bool driverHasFloatRenderTargets() const;
    bool driverHasClipControl() const;
    // gl_ClipDistance in shaders: desktop GL 3.0 on; ES only with GL_EXT_clip_cull_distance (in
    // WebGL 2 WEBGL_clip_cull_distance, listed as GL_WEBGL_clip_cull_distance).
    bool driverHasClipDistances() const;
    // GL_DEPTH_CLAMP: desktop GL 3.2 on; ES only with GL_EXT_depth_clamp.
    bool driverHasDepthClamp() const;
    // 16-bit unorm colour targets (GL_RG16) renderable: desktop GL 3.0 on; ES only with
    // GL_EXT_texture_norm16 (WebGL 2's EXT_texture_norm16).
    bool driverHasNorm16Targets() const;

    // The driver's answer with the forced fallbacks applied; `reason` (optional) says why.
    bool ssboAvailable(std::string* reason = nullptr) const;
    bool computeAvailable(std::string* reason = nullptr) const;  // compute shaders and SSBOs both
    bool stencilTexturingAvailable(std::string* reason = nullptr) const;
    bool dsaAvailable(std::string* reason = nullptr) const;
    bool debugOutputAvailable(std::string* reason = nullptr) const;
    bool floatRenderTargetsAvailable(std::string* reason = nullptr) const;
    bool clipControlAvailable(std::string* reason = nullptr) const;  // glClipControl: reversed-z depth
    bool clipDistancesAvailable(std::string* reason = nullptr) const;  // else a varying and discard
    // The GLSL ES #extension that brings gl_ClipDistance where clipDistancesAvailable():
    // GL_EXT_clip_cull_distance, or in WebGL 2 GL_ANGLE_clip_cull_distance (its directive).
    std::string clipDistanceDirective() const;
    bool depthClampAvailable(std::string* reason = nullptr) const;  // else shadow casters pancaked in the shader
    // 16-bit unorm colour targets (the compact G-buffer's RG16 normal), else the standard layout is
    // drawn. The driver's own extension list decides, not a forced tier's: --force gles30 hides
    // EXT_texture_norm16 from the report but not from the driver, whose RG16 targets still draw.
    bool norm16TargetsAvailable(std::string* reason = nullptr) const;
    // Depth-testing against the depth-stencil texture a draw also samples, with depth and stencil
    // writes off: GL 4.5's feedback-loop rule (or ARB_texture_barrier's) makes only texels a draw
    // writes undefined to read. Else the compact lighting that samples depth in place shades every pixel.
    bool readOnlyDepthAvailable(std::string* reason = nullptr) const;
    // glReadPixels of depth and stencil (desktop; ES with GL_NV_read_depth_stencil), else they are
    // read by drawing (render/depth_stencil_readback.h).
    bool depthStencilReadAvailable(std::string* reason = nullptr) const;
    // "OpenGL 4.5" / "OpenGL ES 3.2": the version as the reasons name it.
    std::string apiVersionName() const;

    // The driver's own capabilities: the forced tier undone (beforeTier), nothing forced. Their
    // *Available() say what this driver could do.
    Capabilities unforced() const;
    // One *Available() asked of the driver's own capabilities and of these:
    // availability(&Capabilities::clipControlAvailable).
    Availability availability(bool (Capabilities::*available)(std::string*) const) const;

    // The extensions oasis cares about (each with whether the context lists it), in a fixed order.
    std::vector<std::pair<std::string, bool>> relevantExtensions() const;
};

// Applies the forced tier of caps.forced to a context's measured version and extensions: gles30
// makes an ES 3.1+ context 3.0 keeping only the extensions an ES 3.0 device lists too (float
// colour targets, debug output), gl33 caps a context above 3.3 at 3.3
// (the version strings say so); what the context gave goes to beforeTier. Nothing else forced
// changes here: the *Available() apply the rest.
void applyForcedTier(Capabilities& caps);

// Measures the current context (needs one made current); `forced` is kept alongside and its tier
// applied (applyForcedTier).
Capabilities measureCapabilities(const ForcedFallbacks& forced = {});

}  // namespace oasis::gl
