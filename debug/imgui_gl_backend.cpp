// The ImGui OpenGL3 backend build chosen by the context's API (debug/imgui_gl_backend.h).
#include "debug/imgui_gl_backend.h"

#include <epoxy/gl.h>
#include <imgui_impl_opengl3.h>

#include "debug/imgui_gles/imgui_impl_opengl3_gles.h"

namespace oasis {

bool imguiGlBackendInit() {
    bool es = !epoxy_is_desktop_gl();
    if (es) ImGui_ImplOpenGL3Es_Init("#version 300 es");
    else ImGui_ImplOpenGL3_Init("#version 330 core");
    return es;
}

void imguiGlBackendNewFrame(bool es) {
    if (es) ImGui_ImplOpenGL3Es_NewFrame();
    else ImGui_ImplOpenGL3_NewFrame();
}

void imguiGlBackendRender(bool es, ImDrawData* data) {
    if (es) ImGui_ImplOpenGL3Es_RenderDrawData(data);
    else ImGui_ImplOpenGL3_RenderDrawData(data);
}

void imguiGlBackendShutdown(bool es) {
    if (es) ImGui_ImplOpenGL3Es_Shutdown();
    else ImGui_ImplOpenGL3_Shutdown();
}

}  // namespace oasis
