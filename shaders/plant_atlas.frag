// Plant segments in the atlas: the colour the vertex shader chose, opaque (the atlas background
// stays transparent).
in vec3 vColour;
layout(location = 0) out vec4 outColour;

void main() { outColour = vec4(vColour, 1.0); }
