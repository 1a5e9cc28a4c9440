// The timing floor: the cheapest possible full-screen G-buffer write (FLOOR_WRITE) and read
// (FLOOR_READ) at the frame's formats. Pipelines are reported as multiples of the two together.
#if defined(FLOOR_WRITE)
layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outPosition;
layout(location = 3) out vec4 outInfo;
void main() {
    vec4 v = vec4(gl_FragCoord.xy * 1e-3, 0.5, 1.0);
    outAlbedo = v; outNormal = v.yxzw; outPosition = v.zyxw; outInfo = v.wzyx;
}
#elif defined(FLOOR_READ)
uniform sampler2D gAlbedo;
uniform sampler2D gNormal;
uniform sampler2D gPosition;
uniform sampler2D gInfo;
layout(location = 0) out vec4 outColour;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    outColour = texelFetch(gAlbedo, p, 0) + texelFetch(gNormal, p, 0) + texelFetch(gPosition, p, 0)
              + texelFetch(gInfo, p, 0);
}
#else
#error "define FLOOR_WRITE or FLOOR_READ"
#endif
