// Stand-in for <GLES3/gl3.h> (copied under that name into the build tree) when Dear ImGui's
// OpenGL3 backend is built for OpenGL ES 3
// (IMGUI_IMPL_OPENGL_ES3, the imgui_backend_gles library in CMakeLists.txt): libepoxy, already
// included, declares the ES 3 entry points and resolves them at run time, as for desktop GL.
// Include order: the backend's -include epoxy/gl.h, then this from the backend's GL includes.
#pragma once
#include <epoxy/gl.h>
// libepoxy defines every API's enums; the backend takes GL_POLYGON_MODE's presence to mean
// glPolygonMode exists, which it does not on ES.
#undef GL_POLYGON_MODE
