// --gl-debug and object labels on the real context: a deliberate GL error is caught inside the
// call (synchronous output) with the debug group path around it; every object a deferred frame
// uses carries its label (glGetObjectLabel), G-buffer targets by role and layout.
#include "gpu_test.h"

#include "context/gl_context.h"
#include "gl/objects.h"

namespace oasis::gputest {
namespace {

std::string gStopped;
void recordStop(const std::string& message) { gStopped = message; }

class GlDebug : public GpuTest {};

TEST_F(GlDebug, FirstErrorNamesItsDebugGroupPath) {
    if (!gl::hasDebugGroups()) GTEST_SKIP() << "no KHR_debug on this context";
    void* harnessCallback = nullptr;  // the suite's own (main.cpp): put back afterwards
    glGetPointerv(GL_DEBUG_CALLBACK_FUNCTION, &harnessCallback);
    setGlDebugMode(true);
    installDebugOutput();  // synchronous from here on
    setGlErrorStop(recordStop);
    gStopped.clear();
    int errorsBefore = glDebugCounts().errors;
    {
        gl::DebugGroup outer("OuterPass");
        gl::DebugGroup inner("InnerStep");
        glEnable(0xffff);  // GL_INVALID_ENUM, reported before glEnable returns
        EXPECT_NE(gStopped.find("OuterPass / InnerStep"), std::string::npos) << "stop message: " << gStopped;
    }
    while (glGetError() != GL_NO_ERROR) {}
    EXPECT_EQ(glDebugCounts().errors, errorsBefore + 1);
    setGlErrorStop(nullptr);
    setGlDebugMode(false);
    glDebugMessageCallback(reinterpret_cast<GLDEBUGPROC>(harnessCallback), nullptr);
}

class ObjectLabels : public GpuTest {};

TEST_F(ObjectLabels, DeferredFrameTargetsAreNamedByRoleAndLayout) {
    if (!gl::hasObjectLabels()) GTEST_SKIP() << "no KHR_debug on this context";
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(64, 36, layoutNamed("compact"));
    renderer.renderFrame(pose.scene);
    const FrameTargets& targets = renderer.targets();
    EXPECT_EQ(gl::objectLabel(gl::ObjectKind::Texture, targets.texture(Target::Albedo)), "G-buffer albedo (compact)");
    EXPECT_EQ(gl::objectLabel(gl::ObjectKind::Texture, targets.texture(Target::SceneDepth)), "SceneDepth copy");
    EXPECT_EQ(gl::objectLabel(gl::ObjectKind::Texture, targets.texture(Target::Reflection)), "Reflection");
    EXPECT_EQ(gl::objectLabel(gl::ObjectKind::Program, renderer.parts().shaders.program("lighting.compact")),
              "lighting.compact");
    // Every live buffer, texture, framebuffer, vertex array, program and sampler has a label (this test's
    // renderer and shader library are the only makers of objects left: earlier tests' are deleted).
    int unnamed = 0, named = 0;
    const std::pair<gl::ObjectKind, GLboolean (*)(GLuint)> kinds[] = {
        {gl::ObjectKind::Texture, [](GLuint n) { return glIsTexture(n); }},
        {gl::ObjectKind::Buffer, [](GLuint n) { return glIsBuffer(n); }},
        {gl::ObjectKind::Framebuffer, [](GLuint n) { return glIsFramebuffer(n); }},
        {gl::ObjectKind::VertexArray, [](GLuint n) { return glIsVertexArray(n); }},
        {gl::ObjectKind::Program, [](GLuint n) { return glIsProgram(n); }},
        {gl::ObjectKind::Sampler, [](GLuint n) { return glIsSampler(n); }}};
    // Names up to 2^16: a driver may hand out names past every one deleted before (zink did, past
    // 4096, in the whole binary's run), so a shorter scan missed this test's own objects.
    for (GLuint name = 1; name < 65536; ++name)
        for (const auto& [kind, alive] : kinds)
            if (alive(name)) {
                bool hasLabel = !gl::objectLabel(kind, name).empty();
                (hasLabel ? named : unnamed) += 1;
                if (!hasLabel) ADD_FAILURE() << "object " << name << " of kind " << int(kind) << " has no label";
            }
    EXPECT_GT(named, 30);
    EXPECT_EQ(unnamed, 0);
}

}  // namespace
}  // namespace oasis::gputest
