// debug/imgui_gl_backend.h for the page: a WebGL 2 context is always OpenGL ES 3.0, so only Dear
// ImGui's OpenGL ES 3 backend is built (IMGUI_IMPL_OPENGL_ES3, src/web/CMakeLists.txt).
#include "debug/imgui_gl_backend.h"

#include <imgui_impl_opengl3.h>

namespace oasis {

bool imguiGlBackendInit() {
    ImGui_ImplOpenGL3_Init("#version 300 es");
    return true;
}
void imguiGlBackendNewFrame(bool) { ImGui_ImplOpenGL3_NewFrame(); }
void imguiGlBackendRender(bool, ImDrawData* data) { ImGui_ImplOpenGL3_RenderDrawData(data); }
void imguiGlBackendShutdown(bool) { ImGui_ImplOpenGL3_Shutdown(); }

}  // namespace oasis
