// Dear ImGui's OpenGL3 backend built a second time for OpenGL ES 3 (no glPolygonMode, GLSL
// "#version 300 es"; the imgui_backend_gles library in CMakeLists.txt), its entry points renamed
// so they link beside the desktop build's. LabelOverlay picks one by the current context's API.
#pragma once
struct ImDrawData;

bool ImGui_ImplOpenGL3Es_Init(const char* glsl_version);
void ImGui_ImplOpenGL3Es_Shutdown();
void ImGui_ImplOpenGL3Es_NewFrame();
void ImGui_ImplOpenGL3Es_RenderDrawData(ImDrawData* draw_data);
