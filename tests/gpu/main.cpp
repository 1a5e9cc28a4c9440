// Entry point of the GPU tests: one headless EGL context for the whole process (a gtest
// environment), GL debug errors captured for the fixture; no context means every test fails.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "gl/capabilities.h"

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

// The driver set-up ctest asked for ($OASIS_GPU_SETUP, set with the environment that selects it):
// "" (whatever the default driver is), llvmpipe, zink, softpipe, no-ssbo-compute, gles or gles31. Returns why
// the context is not that set-up ("" when it is), so a missing driver skips instead of silently
// testing another one.
std::string setupMismatch(const std::string& setup, const ContextInfo& info) {
    auto renderedBy = [&](const char* name) { return info.renderer.find(name) != std::string::npos; };
    std::string context = "the context is " + info.summary();
    if (setup.empty()) return {};
    if (setup == "llvmpipe" || setup == "zink" || setup == "softpipe")
        return renderedBy(setup.c_str()) ? "" : setup + " is not available here: " + context;
    if (setup == "gles") {
        if (epoxy_is_desktop_gl()) return "gles needs an OpenGL ES context (OASIS_API=gles): " + context;
        return {};
    }
    if (setup == "gles31") {  // Mesa's MESA_GLES_VERSION_OVERRIDE=3.1 on an ES context
        if (epoxy_is_desktop_gl() || epoxy_gl_version() != 31)
            return "gles31 needs an OpenGL ES 3.1 context (OASIS_API=gles, MESA_GLES_VERSION_OVERRIDE=3.1): " + context;
        return {};
    }
    if (setup == "no-ssbo-compute") {
        gl::Capabilities caps = gl::measureCapabilities();
        if (!renderedBy("llvmpipe")) return "no-ssbo-compute needs llvmpipe: " + context;
        if (caps.driverHasSsbo() || caps.driverHasCompute())
            return "MESA_EXTENSION_OVERRIDE did not remove SSBOs and compute shaders: " + context;
        return {};
    }
    return "unknown OASIS_GPU_SETUP '" + setup + "'";
}

class GpuEnvironment : public ::testing::Environment {
public:
    void SetUp() override {
        GpuState& state = gpuState();
        const char* setupVariable = std::getenv("OASIS_GPU_SETUP");
        std::string setup = setupVariable ? setupVariable : "";
        // $OASIS_API=gles: the whole suite on an OpenGL ES 3.x context (the shader library speaks
        // GLSL ES there: glslDialectForCurrentContext); unset or gl: desktop OpenGL core.
        const char* apiVariable = std::getenv("OASIS_API");
        std::string api = apiVariable ? apiVariable : "gl";
        if (api != "gl" && api != "gles") {
            ADD_FAILURE() << "OASIS_API must be gl or gles, not '" << api << "'";
            return;
        }
        try {
            state.context = std::make_unique<HeadlessContext>(api == "gles" ? MaxGlVersion{3, 2, true} : MaxGlVersion{});
        } catch (const std::exception& error) {
            state.error = error.what();
            if (!setup.empty()) {
                state.skipReason = "driver set-up " + setup + " is not available here: " + state.error;
                std::printf("[gpu] SKIPPED: %s\n", state.skipReason.c_str());
                return;
            }
            ADD_FAILURE() << "cannot create the headless OpenGL context: " << state.error;
            return;
        }
        state.info = queryContextInfo();
        std::printf("[gpu] %s%s\n", setup.empty() ? "" : ("set-up " + setup + ": ").c_str(),
                    state.info.summary().c_str());
        state.skipReason = setupMismatch(setup, state.info);
        if (!state.skipReason.empty()) std::printf("[gpu] SKIPPED: %s\n", state.skipReason.c_str());
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
    int result = RUN_ALL_TESTS();
    // A whole-suite run for a driver set-up that is not here: say why, and exit with the code
    // ctest's SKIP_RETURN_CODE turns into "Skipped" (never a silent pass).
    const std::string& skipped = oasis::gputest::gpuState().skipReason;
    if (!skipped.empty()) {
        std::fprintf(stderr, "oasis_gpu_tests: SKIPPED: %s\n", skipped.c_str());
        return 77;
    }
    return result;
}
