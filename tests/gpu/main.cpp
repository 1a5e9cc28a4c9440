// Entry point of the GPU tests: one headless EGL context for the whole process (a gtest
// environment), GL debug errors captured for the fixture; no context means every test fails.
#include <gtest/gtest.h>

#include <cstdio>

#include "gpu_test.h"

namespace oasis::gputest {

GpuState& gpuState() {
    static GpuState state;
    return state;
}

namespace {

void GLAPIENTRY captureDebugMessage(GLenum source, GLenum type, GLuint, GLenum severity, GLsizei,
                                    const GLchar* message, const void*) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    // Compile errors of deliberately broken shaders are reported by the library; API errors are bugs.
    if (type == GL_DEBUG_TYPE_ERROR && source != GL_DEBUG_SOURCE_SHADER_COMPILER)
        gpuState().glErrors.push_back(message);
}

class GpuEnvironment : public ::testing::Environment {
public:
    void SetUp() override {
        GpuState& state = gpuState();
        try {
            state.context = std::make_unique<HeadlessContext>();
        } catch (const std::exception& error) {
            state.error = error.what();
            ADD_FAILURE() << "cannot create the headless OpenGL context: " << state.error;
            return;
        }
        state.info = queryContextInfo();
        std::printf("[gpu] %s\n", state.info.summary().c_str());
        if (epoxy_gl_version() >= 43 || epoxy_has_gl_extension("GL_KHR_debug")) {
            glEnable(GL_DEBUG_OUTPUT);
            glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
            glDebugMessageCallback(captureDebugMessage, nullptr);
        }
    }
    void TearDown() override { gpuState().context.reset(); }
};

}  // namespace
}  // namespace oasis::gputest

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    ::testing::AddGlobalTestEnvironment(new oasis::gputest::GpuEnvironment);
    return RUN_ALL_TESTS();
}
