// Depth and stencil read back by drawing (render/depth_stencil_readback.h), where glReadPixels cannot
// read them: OpenGL ES reads depth and stencil only with GL_NV_read_depth_stencil, which WebGL 2 and
// most ES drivers lack. READ_DEPTH: the depth-stencil texture's depth at the pixel, into a float
// target. READ_STENCIL_BIT: the value of one stencil bit, drawn where the stencil test finds it
// set and added up by blending into an 8-bit target, one draw a bit. READ_SHADOW_LAYER: one layer of
// the sun's shadow maps (their compare mode turned off for the read), for the check's shading oracle.
layout(location = 0) out vec4 outValue;

#if defined(READ_SHADOW_LAYER)
uniform highp sampler2DArray shadowMap;  // bound to the shadow maps' unit by name
uniform int shadowLayer;

void main() {
    outValue = vec4(texelFetch(shadowMap, ivec3(ivec2(gl_FragCoord.xy), shadowLayer), 0).r, 0.0, 0.0, 1.0);
}
#elif defined(READ_DEPTH)
uniform sampler2D sourceTexture;  // the depth-stencil texture: ES 3.0 samples its depth

void main() {
    outValue = vec4(texelFetch(sourceTexture, ivec2(gl_FragCoord.xy), 0).r, 0.0, 0.0, 1.0);
}
#else
uniform float stencilBitValue;  // 2^bit / 255: the bit's share of the 8-bit unorm target

void main() {
    outValue = vec4(stencilBitValue, 0.0, 0.0, 1.0);
}
#endif
