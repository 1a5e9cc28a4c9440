// DepthCopyPass: the G-buffer's depth, pixel for pixel, into SceneDepth by drawing (depth test
// ALWAYS). Drawn rather than blitted: oasis never blits or copies its targets (see the
// capability notes in README: Intel's copy corruption).
uniform sampler2D gDepth;

void main() {
    gl_FragDepth = texelFetch(gDepth, ivec2(gl_FragCoord.xy), 0).r;
}
