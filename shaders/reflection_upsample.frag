// The reflection drawn at a reduced resolution (--reflection-resolution half|quarter), read
// bilinearly at this pixel's centre: the same point of the screen in the smaller target. Drawn
// stencil-masked to the frame's visible water (passes/reflection_upsample_pass.h).
#include "common/frame_block.glsl"

uniform sampler2D sourceTexture;  // the reduced Reflection, filtered linearly, clamped at its edges
layout(location = 0) out vec4 outColour;

void main() { outColour = texture(sourceTexture, gl_FragCoord.xy * frame.screen.zw); }
