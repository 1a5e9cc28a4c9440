// Dear ImGui's OpenGL3 backend in the build that suits the current context: the desktop one
// ("#version 330 core"), or on OpenGL ES 3 (--api gles) the ES build ("#version 300 es", the
// imgui_backend_gles library), whose desktop twin calls glPolygonMode, absent on ES.
#pragma once
#include <imgui.h>

namespace oasis {

// Initialises the backend for the current ImGui and GL contexts; returns whether it is the ES
// build, which the other calls take back (a context's API never changes).
bool imguiGlBackendInit();
void imguiGlBackendNewFrame(bool es);
void imguiGlBackendRender(bool es, ImDrawData* data);
void imguiGlBackendShutdown(bool es);

}  // namespace oasis
