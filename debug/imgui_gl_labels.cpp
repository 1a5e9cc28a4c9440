// Labels Dear ImGui's backend objects from inside its draw loop (see imgui_gl_labels.h).
#include "debug/imgui_gl_labels.h"

#include <epoxy/gl.h>

#include <cstdint>
#include <string>

#include "gl/objects.h"

namespace oasis {
namespace {

void labelBoundObjects(const ImDrawList*, const ImDrawCmd* command) {
    if (!gl::hasObjectLabels()) return;
    const std::string owner = static_cast<const char*>(command->UserCallbackData);
    GLint program = 0, vertexArray = 0, vertices = 0, indices = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &vertices);
    glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &indices);  // the bound vertex array's
    gl::setLabel(gl::ObjectKind::Program, GLuint(program), owner + " program");
    gl::setLabel(gl::ObjectKind::VertexArray, GLuint(vertexArray), owner + " vertex array");
    gl::setLabel(gl::ObjectKind::Buffer, GLuint(vertices), owner + " vertices");
    gl::setLabel(gl::ObjectKind::Buffer, GLuint(indices), owner + " indices");
    auto font = GLuint(reinterpret_cast<intptr_t>(ImGui::GetIO().Fonts->TexID));
    gl::setLabel(gl::ObjectKind::Texture, font, owner + " font atlas");
}

}  // namespace

void nameImGuiObjects(ImDrawList& list, const char* owner) {
    list.AddCallback(labelBoundObjects, const_cast<char*>(owner));
}

}  // namespace oasis
