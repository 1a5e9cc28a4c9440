// Capability decisions without GL: --force parsing, and each feature's answer for contexts of
// several versions and extension sets (a 3.3 context with and without the ARB extensions, 4.2, 4.5).
#include <gtest/gtest.h>

#include "cli/options.h"
#include "gl/capabilities.h"
#include "render/light_paths.h"

namespace oasis {
namespace {

gl::Capabilities contextOf(int major, int minor, std::set<std::string> extensions = {}) {
    gl::Capabilities caps;
    caps.major = major;
    caps.minor = minor;
    caps.extensions = std::move(extensions);
    // Storage-block limits as llvmpipe reports them on GL 4.5 and ES 3.2 (80 bindings and combined,
    // 16 per stage).
    gl::Limits& l = caps.limits;
    l.maxShaderStorageBufferBindings = l.maxCombinedShaderStorageBlocks = 80;
    l.maxVertexShaderStorageBlocks = l.maxFragmentShaderStorageBlocks = l.maxComputeShaderStorageBlocks = 16;
    return caps;
}

TEST(ForcedFallbacks, ParsesEveryNameAndListsThemBack) {
    gl::ForcedFallbacks forced;
    std::string error;
    ASSERT_TRUE(gl::parseForcedFallbacks("no-ssbo,no-compute,no-stencil-texturing,no-dsa,gl33", forced, error)) << error;
    EXPECT_TRUE(forced.noSsbo && forced.noCompute && forced.noStencilTexturing && forced.noDsa && forced.gl33);
    EXPECT_EQ(forced.list(), "no-ssbo,no-compute,no-stencil-texturing,no-dsa,gl33");
    EXPECT_FALSE(gl::ForcedFallbacks{}.any());
}

TEST(ForcedFallbacks, RejectsUnknownAndEmptyNames) {
    for (const char* bad : {"no-ssbo,fast", "", "no-ssbo,", ",no-dsa", "NO-SSBO"}) {
        gl::ForcedFallbacks forced;
        std::string error;
        EXPECT_FALSE(gl::parseForcedFallbacks(bad, forced, error)) << bad;
        EXPECT_FALSE(error.empty()) << bad;
    }
}

TEST(ForcedFallbacks, CommandLineAcceptsForceOnEverySubcommandAndCapsJson) {
    ParseResult r = parseCommandLine({"render", "--force", "no-ssbo,gl33"});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_TRUE(r.options.scene.force.noSsbo && r.options.scene.force.gl33);
    r = parseCommandLine({"caps", "--json", "--force", "no-dsa"});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.options.command, Command::Caps);
    EXPECT_TRUE(r.options.json && r.options.scene.force.noDsa);
    r = parseCommandLine({"compare", "--force", "no-ssbo,bogus"});
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("bogus"), std::string::npos) << r.error;
    EXPECT_FALSE(parseCommandLine({"caps", "--frames", "3"}).ok);
}

gl::Capabilities esContextOf(int minor, std::set<std::string> extensions = {}) {
    gl::Capabilities caps = contextOf(3, minor, std::move(extensions));
    caps.es = true;
    return caps;
}

// OpenGL ES (--api gles): features by ES version and ES extension, in ES terms.
TEST(Capabilities, EsVersionsAndExtensions) {
    gl::Capabilities es32 = esContextOf(2, {"GL_EXT_clip_control", "GL_EXT_clip_cull_distance", "GL_KHR_debug"});
    std::string reason;
    EXPECT_TRUE(es32.ssboAvailable(&reason));
    EXPECT_NE(reason.find("ES 3.1"), std::string::npos) << reason;
    EXPECT_TRUE(es32.computeAvailable(&reason)) << reason;
    EXPECT_TRUE(es32.stencilTexturingAvailable());
    EXPECT_TRUE(es32.floatRenderTargetsAvailable(&reason));
    EXPECT_NE(reason.find("ES 3.2"), std::string::npos) << reason;
    EXPECT_TRUE(es32.clipControlAvailable(&reason));
    EXPECT_NE(reason.find("GL_EXT_clip_control"), std::string::npos) << reason;
    EXPECT_TRUE(es32.clipDistancesAvailable());
    EXPECT_FALSE(es32.dsaAvailable(&reason)) << "ES has no direct state access";
    EXPECT_EQ(es32.apiVersionName(), "OpenGL ES 3.2");
    // ES 3.0: no storage blocks, compute or stencil texturing; float targets only by extension.
    gl::Capabilities es30 = esContextOf(0);
    EXPECT_FALSE(es30.ssboAvailable(&reason));
    EXPECT_EQ(reason, "no ES 3.1");
    EXPECT_FALSE(es30.computeAvailable());
    EXPECT_FALSE(es30.stencilTexturingAvailable());
    EXPECT_FALSE(es30.floatRenderTargetsAvailable(&reason));
    EXPECT_NE(reason.find("GL_EXT_color_buffer_float"), std::string::npos) << reason;
    EXPECT_FALSE(es30.clipDistancesAvailable(&reason));
    EXPECT_NE(reason.find("GL_EXT_clip_cull_distance"), std::string::npos) << reason;
    EXPECT_FALSE(es30.clipControlAvailable());
    EXPECT_TRUE(esContextOf(0, {"GL_EXT_color_buffer_float"}).floatRenderTargetsAvailable());
    // A desktop context is not answered by ES extensions.
    EXPECT_FALSE(contextOf(4, 5, {"GL_EXT_clip_control"}).es);
    EXPECT_TRUE(contextOf(3, 3).clipDistancesAvailable()) << "desktop GL 3.0 has gl_ClipDistance";
}

// ES 3.1 has storage blocks, but guarantees only 4 bindings and 4 blocks per program, none in the
// vertex and fragment stages: there the light list takes the UBO path and the plants the CPU,
// each saying which limit fell short, though the version alone would allow both.
TEST(Capabilities, EsStorageLimitsBelowWhatOasisNeedsTakeTheFallbacks) {
    gl::Capabilities es31 = esContextOf(1, {"GL_EXT_gpu_shader5"});  // the interpreter's `precise`
    ASSERT_TRUE(es31.driverHasSsbo() && es31.driverHasCompute());
    std::string reason;
    EXPECT_TRUE(es31.ssboAvailable()) << "llvmpipe's limits are enough";
    gl::Limits& l = es31.limits;
    l.maxShaderStorageBufferBindings = 4;  // ES 3.1's minimums
    l.maxVertexShaderStorageBlocks = l.maxFragmentShaderStorageBlocks = 0;
    l.maxComputeShaderStorageBlocks = l.maxCombinedShaderStorageBlocks = 4;
    EXPECT_FALSE(es31.ssboAvailable(&reason));
    EXPECT_EQ(reason, "SSBOs present (ES 3.1) but GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS is 4, the SSBO light list "
                      "needs 8");
    EXPECT_FALSE(es31.computeAvailable(&reason));
    EXPECT_EQ(reason.rfind("compute needs SSBOs: ", 0), 0u) << reason;
    LightsPathChoice lights = chooseLightsPath(es31.ssboAvailable(&reason), LightsPath::Ssbo, reason);
    EXPECT_EQ(lights.path, LightsPath::Ubo);
    EXPECT_NE(lights.reason.find("GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS is 4"), std::string::npos) << lights.reason;
    // Each limit alone: every binding but no storage block in the fragment stage.
    l.maxShaderStorageBufferBindings = 8;
    l.maxVertexShaderStorageBlocks = 2;
    l.maxCombinedShaderStorageBlocks = 8;
    EXPECT_FALSE(es31.ssboAvailable(&reason));
    EXPECT_NE(reason.find("GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS is 0, the SSBO light list needs 4"),
              std::string::npos) << reason;
    l.maxFragmentShaderStorageBlocks = 3;
    EXPECT_FALSE(es31.ssboAvailable()) << "one block short: light list, count, tiles and water bounds";
    l.maxFragmentShaderStorageBlocks = 4;
    l.maxVertexShaderStorageBlocks = 1;
    EXPECT_FALSE(es31.ssboAvailable(&reason)) << "light_volume.vert reads the list and its count";
    EXPECT_NE(reason.find("GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS is 1"), std::string::npos) << reason;
    l.maxVertexShaderStorageBlocks = 2;
    l.maxCombinedShaderStorageBlocks = 4;
    EXPECT_FALSE(es31.ssboAvailable());
    l.maxCombinedShaderStorageBlocks = 8;
    EXPECT_TRUE(es31.ssboAvailable(&reason)) << reason;
    // The light list fits, the interpreter's 7 buffers do not: SSBO lights, CPU plants.
    EXPECT_FALSE(es31.computeAvailable(&reason));
    EXPECT_EQ(reason, "compute shaders present (ES 3.1) but GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS is 4, the compute "
                      "plant interpretation needs 7");
    l.maxComputeShaderStorageBlocks = 7;
    EXPECT_TRUE(es31.computeAvailable(&reason)) << reason;
    l.maxShaderStorageBufferBindings = 7;  // the light count's binding 7 is one past
    EXPECT_FALSE(es31.ssboAvailable());
    // Desktop GL answers from the same limits (GL 4.3 allows 0 vertex-stage blocks too).
    gl::Capabilities gl43 = contextOf(4, 3);
    gl43.limits.maxVertexShaderStorageBlocks = 0;
    EXPECT_FALSE(gl43.ssboAvailable(&reason));
    EXPECT_NE(reason.find("GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS is 0"), std::string::npos) << reason;
}

// ES 3.1 has compute shaders but `precise` (the interpreter's exact rounding) only with EXT_ or
// OES_gpu_shader5: with either the GPU path, without both the CPU one, saying so before any compile.
TEST(Capabilities, Es31PlantInterpreterNeedsGpuShader5) {
    std::string reason;
    EXPECT_TRUE(esContextOf(1, {"GL_EXT_gpu_shader5", "GL_OES_gpu_shader5"}).computeAvailable(&reason)) << reason;
    EXPECT_EQ(reason, "compute shaders and SSBOs present (ES 3.1), precise by GL_EXT_gpu_shader5");
    EXPECT_TRUE(esContextOf(1, {"GL_OES_gpu_shader5"}).computeAvailable(&reason)) << reason;
    EXPECT_EQ(reason, "compute shaders and SSBOs present (ES 3.1), precise by GL_OES_gpu_shader5");
    gl::Capabilities bare = esContextOf(1);
    EXPECT_TRUE(bare.driverHasCompute() && bare.ssboAvailable());
    EXPECT_FALSE(bare.computeAvailable(&reason));
    EXPECT_EQ(reason, "compute shaders present but no ES 3.2 / GL_EXT_gpu_shader5 / GL_OES_gpu_shader5 (precise) "
                      "for its GLSL");
    EXPECT_TRUE(esContextOf(2).computeAvailable(&reason)) << "core in ES 3.2: " << reason;
    EXPECT_EQ(reason, "compute shaders and SSBOs present (ES 3.1)");
}

// --force gles30 on an ES 3.2 driver with the extensions: the tier hides them, and the report says
// the tier limits them while the driver has them (issue 29: it said "the driver has no ...").
TEST(Capabilities, ForcedEs30TierIsTheLimitWhereTheDriverHasTheFeature) {
    gl::Capabilities caps = esContextOf(2, {"GL_EXT_clip_control", "GL_EXT_clip_cull_distance", "GL_EXT_depth_clamp",
                                            "GL_EXT_color_buffer_float", "GL_KHR_debug"});
    caps.forced.gles30 = true;
    gl::applyForcedTier(caps);
    EXPECT_EQ(caps.minor, 0);
    ASSERT_TRUE(caps.beforeTier.has_value());
    EXPECT_EQ(caps.beforeTier->minor, 2);
    EXPECT_FALSE(caps.hasExtension("GL_EXT_clip_control")) << "the tier's own extensions alone";
    EXPECT_TRUE(caps.driverHasClipControl() && caps.driverHasClipDistances() && caps.driverHasDepthClamp() &&
                caps.driverHasSsbo())
        << "the driver's answer ignores the tier";
    gl::Availability clip = caps.availability(&gl::Capabilities::clipControlAvailable);
    EXPECT_TRUE(clip.driver);
    EXPECT_FALSE(clip.tier);
    EXPECT_EQ(clip.reason,
              "no GL_EXT_clip_control in the forced ES 3.0 tier (--force gles30; the driver has GL_EXT_clip_control)");
    EXPECT_EQ(gl::limitedBy(false, clip), gl::kLimitedByForcedTier);
    for (auto available : {&gl::Capabilities::clipDistancesAvailable, &gl::Capabilities::depthClampAvailable,
                           &gl::Capabilities::ssboAvailable, &gl::Capabilities::stencilTexturingAvailable}) {
        gl::Availability each = caps.availability(available);
        EXPECT_TRUE(each.driver && !each.tier) << each.reason;
        EXPECT_NE(each.reason.find("in the forced ES 3.0 tier (--force gles30; the driver has "), std::string::npos)
            << each.reason;
        EXPECT_EQ(gl::limitedBy(false, each), gl::kLimitedByForcedTier) << each.reason;
    }
    EXPECT_EQ(caps.availability(&gl::Capabilities::ssboAvailable).reason,
              "no ES 3.1 in the forced ES 3.0 tier (--force gles30; the driver has ES 3.1)");
    // What the ES 3.0 tier keeps is used: float targets by the extension, debug output.
    gl::Availability floats = caps.availability(&gl::Capabilities::floatRenderTargetsAvailable);
    EXPECT_TRUE(floats.driver && floats.tier) << floats.reason;
    EXPECT_EQ(gl::limitedBy(true, floats), "");
    EXPECT_TRUE(caps.unforced().clipControlAvailable()) << "the driver's own capabilities";
}

// The same tier on a driver without the extensions: the driver is the limit, said in its terms.
TEST(Capabilities, ForcedEs30TierOnADriverWithoutTheExtensionsBlamesTheDriver) {
    gl::Capabilities caps = esContextOf(2, {"GL_EXT_color_buffer_float"});
    caps.forced.gles30 = true;
    gl::applyForcedTier(caps);
    gl::Availability clip = caps.availability(&gl::Capabilities::clipControlAvailable);
    EXPECT_FALSE(clip.driver || clip.tier);
    EXPECT_EQ(clip.reason, "no GL_EXT_clip_control");
    EXPECT_EQ(gl::limitedBy(false, clip), gl::kLimitedByDriver);
    // SSBOs: ES 3.2 has them, the tier hides them.
    EXPECT_EQ(gl::limitedBy(false, caps.availability(&gl::Capabilities::ssboAvailable)), gl::kLimitedByForcedTier);
    // Unforced, a driver that has clip control and is not asked for reversed-z: not asked for.
    gl::Capabilities plain = esContextOf(2, {"GL_EXT_clip_control"});
    EXPECT_EQ(gl::limitedBy(false, plain.availability(&gl::Capabilities::clipControlAvailable)),
              gl::kLimitedByNotAskedFor);
    EXPECT_FALSE(plain.beforeTier.has_value());
}

// 16-bit unorm colour targets (the compact G-buffer's RG16 normal): desktop GL 3.0 core; ES only
// with EXT_texture_norm16 (emscripten lists WebGL's name with and without GL_), the driver's own
// list deciding under --force gles30 (the tier hides the extension, not the driver's targets).
TEST(Capabilities, Norm16TargetsOnEsOnlyWithTheDriversOwnExtension) {
    std::string reason;
    gl::Capabilities without = esContextOf(0, {"GL_EXT_color_buffer_float"});
    EXPECT_FALSE(without.norm16TargetsAvailable(&reason));
    EXPECT_EQ(reason, "no GL_EXT_texture_norm16 on this OpenGL ES driver");
    EXPECT_EQ(gl::limitedBy(false, without.availability(&gl::Capabilities::norm16TargetsAvailable)), gl::kLimitedByDriver);
    EXPECT_TRUE(esContextOf(0, {"EXT_texture_norm16"}).norm16TargetsAvailable());
    gl::Capabilities forced = esContextOf(2, {"GL_EXT_texture_norm16", "GL_EXT_color_buffer_float"});
    forced.forced.gles30 = true;
    gl::applyForcedTier(forced);
    EXPECT_FALSE(forced.hasExtension("GL_EXT_texture_norm16")) << "the tier's list hides it";
    EXPECT_TRUE(forced.norm16TargetsAvailable(&reason)) << reason;
    EXPECT_NE(reason.find("the driver's own"), std::string::npos) << reason;
    gl::Capabilities desktop;
    desktop.major = 3;
    EXPECT_TRUE(desktop.norm16TargetsAvailable(&reason));
    EXPECT_EQ(reason, "16-bit unorm colour-renderable (core since GL 3.0)");
}

// WebGL 2's clip distances are WEBGL_clip_cull_distance (listed GL_WEBGL_clip_cull_distance by
// emscripten), whose GLSL directive is GL_ANGLE_clip_cull_distance; under the page's forced ES 3.0
// tier the tier, not the driver, is their limit.
TEST(Capabilities, WebglClipDistancesAreTheDriversAndTheirDirectiveIsAngles) {
    gl::Capabilities webgl = esContextOf(0, {"GL_WEBGL_clip_cull_distance", "WEBGL_clip_cull_distance",
                                             "GL_EXT_color_buffer_float"});
    std::string reason;
    EXPECT_TRUE(webgl.clipDistancesAvailable(&reason));
    EXPECT_EQ(reason, "gl_ClipDistance present (GL_WEBGL_clip_cull_distance)");
    EXPECT_EQ(webgl.clipDistanceDirective(), "GL_ANGLE_clip_cull_distance");
    EXPECT_EQ(esContextOf(2, {"GL_EXT_clip_cull_distance"}).clipDistanceDirective(), "GL_EXT_clip_cull_distance");
    webgl.forced.gles30 = true;
    gl::applyForcedTier(webgl);
    gl::Availability clip = webgl.availability(&gl::Capabilities::clipDistancesAvailable);
    EXPECT_TRUE(clip.driver && !clip.tier) << clip.reason;
    EXPECT_EQ(gl::limitedBy(false, clip), gl::kLimitedByForcedTier);
    EXPECT_NE(clip.reason.find("in the forced ES 3.0 tier (--force gles30; the driver has GL_WEBGL_clip_cull_distance)"),
              std::string::npos) << clip.reason;
}

// --force NAME switches a feature off where the driver has it: the forced tier limits it, and a
// context with nothing to cap keeps no beforeTier.
TEST(Capabilities, ForcedFallbacksAreTheForcedTiersLimit) {
    gl::Capabilities caps = contextOf(4, 5, {"GL_KHR_debug"});
    caps.forced.noSsbo = caps.forced.noDepthClamp = true;
    gl::applyForcedTier(caps);
    EXPECT_FALSE(caps.beforeTier.has_value());
    for (auto available : {&gl::Capabilities::ssboAvailable, &gl::Capabilities::computeAvailable,
                           &gl::Capabilities::depthClampAvailable}) {
        gl::Availability each = caps.availability(available);
        EXPECT_EQ(gl::limitedBy(false, each), gl::kLimitedByForcedTier) << each.reason;
        EXPECT_NE(each.reason.find("--force no-"), std::string::npos) << each.reason;
    }
    // --force gl33 on a driver that gave 4.5 (not Mesa: its context is made 3.3): capped, the
    // driver's 4.5 kept for the report.
    gl::Capabilities gl45 = contextOf(4, 5);
    gl45.forced.gl33 = true;
    gl::applyForcedTier(gl45);
    EXPECT_EQ(gl45.minor, 3);
    ASSERT_TRUE(gl45.beforeTier.has_value());
    gl::Availability ssbo = gl45.availability(&gl::Capabilities::ssboAvailable);
    EXPECT_TRUE(ssbo.driver && !ssbo.tier);
    EXPECT_EQ(ssbo.reason, "no GL 4.3 / GL_ARB_shader_storage_buffer_object in the forced GL 3.3 tier (--force gl33; "
                           "the driver has GL 4.3)");
}

TEST(Capabilities, ApiOptionAndTheEsTierForcing) {
    ParseResult r = parseCommandLine({"render", "--api", "gles", "--force", "gles30"});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.options.scene.api, gl::Api::Gles);
    EXPECT_TRUE(r.options.scene.force.gles30);
    EXPECT_EQ(parseCommandLine({"render"}).options.scene.api, gl::Api::Gl);
    EXPECT_TRUE(parseCommandLine({"caps", "--api", "gl"}).ok);
    EXPECT_TRUE(parseCommandLine({"window", "--api", "gles", "--force", "gles30"}).ok) << "the window runs on ES too";
    for (std::vector<std::string> bad : {std::vector<std::string>{"render", "--api", "vulkan"},
                                         {"render", "--force", "gles30"},
                                         {"render", "--api", "gles", "--force", "gl33"},
                                         {"render", "--api"}}) {
        ParseResult refused = parseCommandLine(bad);
        EXPECT_FALSE(refused.ok) << bad.back();
        EXPECT_FALSE(refused.error.empty());
    }
    EXPECT_NE(parseCommandLine({"render", "--force", "gles30"}).error.find("--api gles"), std::string::npos);
}

TEST(Capabilities, ModernContextHasEverythingUntilForcedOff) {
    gl::Capabilities caps = contextOf(4, 5);
    EXPECT_TRUE(caps.ssboAvailable() && caps.computeAvailable() && caps.stencilTexturingAvailable() &&
                caps.dsaAvailable() && caps.debugOutputAvailable() && caps.floatRenderTargetsAvailable());
    caps.forced.noSsbo = true;
    std::string reason;
    EXPECT_FALSE(caps.ssboAvailable(&reason));
    EXPECT_NE(reason.find("--force no-ssbo"), std::string::npos) << reason;
    EXPECT_FALSE(caps.computeAvailable(&reason)) << "the interpreter's buffers are SSBOs";
    EXPECT_NE(reason.find("--force no-ssbo"), std::string::npos) << reason;
    caps.forced = {};
    caps.forced.noCompute = true;
    EXPECT_TRUE(caps.ssboAvailable());
    EXPECT_FALSE(caps.computeAvailable());
    caps.forced.noStencilTexturing = caps.forced.noDsa = true;
    EXPECT_FALSE(caps.stencilTexturingAvailable());
    EXPECT_FALSE(caps.dsaAvailable());
    EXPECT_TRUE(caps.driverHasStencilTexturing() && caps.driverHasDsa()) << "the driver's own answer ignores --force";
}

TEST(Capabilities, PlainGl33HasNoneOfTheOptionalFeatures) {
    gl::Capabilities caps = contextOf(3, 3);
    std::string reason;
    EXPECT_FALSE(caps.ssboAvailable(&reason));
    EXPECT_NE(reason.find("GL_ARB_shader_storage_buffer_object"), std::string::npos) << reason;
    EXPECT_FALSE(caps.computeAvailable(&reason));
    EXPECT_NE(reason.find("GL_ARB_compute_shader"), std::string::npos) << reason;
    EXPECT_FALSE(caps.stencilTexturingAvailable());
    EXPECT_FALSE(caps.dsaAvailable());
    EXPECT_FALSE(caps.debugOutputAvailable());
    EXPECT_TRUE(caps.floatRenderTargetsAvailable()) << "core since 3.0";
}

TEST(Capabilities, Gl33WithExtensionsLikeSoftpipe) {
    gl::Capabilities caps = contextOf(3, 3, {"GL_ARB_shader_storage_buffer_object", "GL_ARB_compute_shader",
                                             "GL_ARB_stencil_texturing", "GL_ARB_shading_language_420pack",
                                             "GL_ARB_gpu_shader5", "GL_KHR_debug"});
    EXPECT_TRUE(caps.ssboAvailable() && caps.computeAvailable() && caps.stencilTexturingAvailable() &&
                caps.debugOutputAvailable());
    caps.extensions.erase("GL_ARB_gpu_shader5");  // the interpreter's `precise`
    std::string reason;
    EXPECT_FALSE(caps.computeAvailable(&reason));
    EXPECT_NE(reason.find("GL_ARB_gpu_shader5"), std::string::npos) << reason;
    EXPECT_TRUE(caps.ssboAvailable());
}

TEST(Capabilities, Gl42WithoutSsboOrComputeLikeTheOverriddenLlvmpipe) {
    gl::Capabilities caps = contextOf(4, 2, {"GL_ARB_stencil_texturing", "GL_KHR_debug"});
    EXPECT_FALSE(caps.ssboAvailable());
    EXPECT_FALSE(caps.computeAvailable());
    EXPECT_TRUE(caps.stencilTexturingAvailable());
}

}  // namespace
}  // namespace oasis
