// Window depth back to distance and to the camera-relative position it stands for, under either
// depth convention (frame.depthConvention): the depth debug view, and the layouts that
// reconstruct position from depth instead of storing it.
#ifndef OASIS_DEPTH_GLSL
#define OASIS_DEPTH_GLSL

bool depthReversed() { return frame.depthConvention.x != 0.0; }

// Nothing drawn: the depth the clear leaves.
bool depthAtFarPlane(float depth) { return depthReversed() ? depth <= 0.0 : depth >= 1.0; }

// Distance along the view axis. Written per convention rather than through the inverse matrix,
// which loses the far depths to cancellation in float.
float eyeDepthFromWindowDepth(float depth) {
    float nearPlane = frame.depthRange.x, farPlane = frame.depthRange.y;
    if (depthReversed()) return nearPlane * farPlane / (depth * (farPlane - nearPlane) + nearPlane);
    float ndc = depth * 2.0 - 1.0;
    return 2.0 * nearPlane * farPlane / (farPlane + nearPlane - ndc * (farPlane - nearPlane));
}

// The camera-relative point under screenUv (0..1 over the frame, pixel centres) at that depth:
// the view ray's point on the near plane, scaled out to the eye depth.
vec3 relativePositionFromDepth(vec2 screenUv, float depth) {
    vec4 onNearPlane = frame.inverseViewProjection * vec4(screenUv * 2.0 - 1.0, frame.depthConvention.y, 1.0);
    return onNearPlane.xyz / onNearPlane.w * (eyeDepthFromWindowDepth(depth) / frame.depthRange.x);
}

#endif
