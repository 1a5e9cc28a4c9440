// One plant segment as a line, instanced: per-instance attributes read the segment buffer (the
// compute shader's output or the CPU's upload, same layout); vertex 0 is its start, 1 its end.
layout(location = 0) in vec2 segmentStart;
layout(location = 1) in vec2 segmentEnd;
layout(location = 2) in float segmentDistance;  // F steps from the root to the start

uniform vec2 plantCentre;    // the plant's bounding-box centre, in turtle units
uniform float plantScale;    // turtle units to the cell's clip space
uniform float maxDistance;   // the plant's longest root-to-tip path, in F steps

out vec3 vColour;

void main() {
    bool atEnd = gl_VertexID == 1;
    vec2 position = atEnd ? segmentEnd : segmentStart;
    // Brown at the root, green at the tips: how far along its path from the root the point is.
    float along = (segmentDistance + (atEnd ? 1.0 : 0.0)) / max(maxDistance, 1.0);
    const vec3 bark = vec3(0.42, 0.26, 0.12), leaf = vec3(0.28, 0.66, 0.16);
    vColour = mix(bark, leaf, clamp(along, 0.0, 1.0));
    gl_Position = vec4((position - plantCentre) * plantScale, 0.0, 1.0);
}
