// Names Dear ImGui's own GL objects (its OpenGL3 backend's program, vertex and index buffers, the
// vertex array it makes per draw, the font texture) so captures show them by owner, not "Buffer 12".
#pragma once
#include <imgui.h>

namespace oasis {

// Adds a draw callback to `list` (put it first, before what it draws): when the backend renders,
// the callback finds the backend's objects bound and labels them "<owner> program" and so on.
// The backend's struct is private to its source, so its objects are found by what is bound.
void nameImGuiObjects(ImDrawList& list, const char* owner);

}  // namespace oasis
