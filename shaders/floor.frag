// The timing floor: the cheapest possible full-screen G-buffer write (FLOOR_WRITE) and read
// (FLOOR_READ) at the frame's formats. Pipelines are reported as multiples of the two together.
// GBUFFER_COMPACT: no position target; the read takes depth in its place, as lighting does.
#if defined(FLOOR_WRITE)
layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec4 outNormal;
#if defined(GBUFFER_COMPACT)
layout(location = 2) out vec4 outInfo;  // the slots follow the stored targets (frame_targets.cpp)
#else
layout(location = 2) out vec4 outPosition;
layout(location = 3) out vec4 outInfo;
#endif
void main() {
    vec4 v = vec4(gl_FragCoord.xy * 1e-3, 0.5, 1.0);
    outAlbedo = v; outNormal = v.yxzw; outInfo = v.wzyx;
#if !defined(GBUFFER_COMPACT)
    outPosition = v.zyxw;
#endif
}
#elif defined(FLOOR_READ)
uniform sampler2D gAlbedo;
uniform sampler2D gNormal;
uniform sampler2D gInfo;
#if defined(GBUFFER_COMPACT)
uniform sampler2D gDepth;
#else
uniform sampler2D gPosition;
#endif
layout(location = 0) out vec4 outColour;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
#if defined(GBUFFER_COMPACT)
    vec4 position = texelFetch(gDepth, p, 0);
#else
    vec4 position = texelFetch(gPosition, p, 0);
#endif
    outColour = texelFetch(gAlbedo, p, 0) + texelFetch(gNormal, p, 0) + position + texelFetch(gInfo, p, 0);
}
#else
#error "define FLOOR_WRITE or FLOOR_READ"
#endif
