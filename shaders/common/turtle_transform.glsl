// The turtle's state change as a 2D rigid transform plus distance walked: the GLSL twin of
// TurtleTransform and composeTransforms in src/scene/turtle.{h,cpp}, operation for operation.
// `precise` forbids fused multiply-adds, so the GPU rounds exactly as the CPU composition does.

struct TurtleTransform {
    vec2 rotation;     // (cos, sin) of the heading change
    vec2 translation;
    float distance;    // F steps walked
};

TurtleTransform identityTransform() { return TurtleTransform(vec2(1.0, 0.0), vec2(0.0), 0.0); }

vec2 rotateBy(vec2 rotation, vec2 v) {
    precise vec2 result = vec2(rotation.x * v.x - rotation.y * v.y, rotation.y * v.x + rotation.x * v.y);
    return result;
}

// outer * inner: apply inner in outer's frame (inner happens after outer).
TurtleTransform composeTransforms(TurtleTransform outer, TurtleTransform inner) {
    TurtleTransform result;
    result.rotation = rotateBy(outer.rotation, inner.rotation);
    precise vec2 translation = outer.translation + rotateBy(outer.rotation, inner.translation);
    result.translation = translation;
    result.distance = outer.distance + inner.distance;
    return result;
}
