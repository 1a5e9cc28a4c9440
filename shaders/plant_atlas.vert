// One plant segment as a quad, instanced: per-instance attributes read the segment buffer (the
// compute shader's output or the CPU's upload, same layout); the 4-vertex strip's vertices 0, 2
// are its start and 1, 3 its end, either side of the line. Branches are thick at the root and
// thin at the tips, with square caps so that consecutive segments join without gaps.
layout(location = 0) in vec2 segmentStart;
layout(location = 1) in vec2 segmentEnd;
layout(location = 2) in float segmentDistance;  // F steps from the root to the start

uniform vec2 plantCentre;    // the plant's bounding-box centre, in turtle units
uniform float plantScale;    // turtle units to the cell's clip space
uniform float maxDistance;   // the plant's longest root-to-tip path, in F steps
uniform float texelSize;     // one atlas texel in the cell's clip space (2 / cell size)

out vec3 vColour;

void main() {
    bool atEnd = (gl_VertexID & 1) == 1;
    float side = (gl_VertexID & 2) == 2 ? 1.0 : -1.0;
    vec2 start = (segmentStart - plantCentre) * plantScale, end = (segmentEnd - plantCentre) * plantScale;
    // Brown at the root, green at the tips: how far along its path from the root the point is.
    float along = clamp((segmentDistance + (atEnd ? 1.0 : 0.0)) / max(maxDistance, 1.0), 0.0, 1.0);
    const vec3 bark = vec3(0.42, 0.26, 0.12), leaf = vec3(0.28, 0.66, 0.16);
    vColour = mix(bark, leaf, along);
    // Width in texels: a trunk of 5 at the root down to twigs and foliage of 2.
    float halfWidth = 0.5 * mix(5.0, 2.0, sqrt(along)) * texelSize;
    vec2 direction = end - start;
    float segmentLength = max(sqrt(dot(direction, direction)), 1e-6);
    direction /= segmentLength;
    vec2 across = vec2(-direction.y, direction.x);
    vec2 position = (atEnd ? end + direction * halfWidth : start - direction * halfWidth) + across * side * halfWidth;
    gl_Position = vec4(position, 0.0, 1.0);
}
