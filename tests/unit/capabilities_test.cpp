// Capability decisions without GL: --force parsing, and each feature's answer for contexts of
// several versions and extension sets (a 3.3 context with and without the ARB extensions, 4.2, 4.5).
#include <gtest/gtest.h>

#include "cli/options.h"
#include "gl/capabilities.h"

namespace oasis {
namespace {

gl::Capabilities contextOf(int major, int minor, std::set<std::string> extensions = {}) {
    gl::Capabilities caps;
    caps.major = major;
    caps.minor = minor;
    caps.extensions = std::move(extensions);
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

TEST(Capabilities, ApiOptionAndTheEsTierForcing) {
    ParseResult r = parseCommandLine({"render", "--api", "gles", "--force", "gles30"});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.options.scene.api, gl::Api::Gles);
    EXPECT_TRUE(r.options.scene.force.gles30);
    EXPECT_EQ(parseCommandLine({"render"}).options.scene.api, gl::Api::Gl);
    EXPECT_TRUE(parseCommandLine({"caps", "--api", "gl"}).ok);
    for (std::vector<std::string> bad : {std::vector<std::string>{"render", "--api", "vulkan"},
                                         {"render", "--force", "gles30"},
                                         {"render", "--api", "gles", "--force", "gl33"},
                                         {"window", "--api", "gles"},
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
