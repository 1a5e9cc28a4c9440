// Sky pixels: the procedural sky along the view ray, emitted as an unlit surface flagged SKY so
// the lighting pass copies it instead of shading it.
#include "common/frame_block.glsl"
#include "common/sky.glsl"
#include "common/emit_surface.glsl"

in vec2 vScreenUv;

void main() {
    vec4 farPoint = frame.inverseViewProjection * vec4(vScreenUv * 2.0 - 1.0, 1.0, 1.0);
    vec3 direction = normalize(farPoint.xyz / farPoint.w);
    Surface s;
    s.albedo = displayEncode(skyRadiance(direction));
    s.normal = -direction;
    s.relativePosition = direction * frame.depthRange.y;
    s.specularPower = 1.0;
    s.specularIntensity = 0.0;
    s.flags = SURFACE_SKY | SURFACE_UNLIT;
    emitSurface(s);
}
