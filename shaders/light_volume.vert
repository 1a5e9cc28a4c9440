// A light's volume: the unit sphere mesh (circumscribed, so it contains the whole sphere of
// influence) scaled to the light's radius around its camera-relative position. MIRRORED: around
// the light's mirror image across the water, for the mirrored G-buffer.
#include "common/frame_block.glsl"
#include "common/lights.glsl"

layout(location = 0) in vec3 unitSpherePosition;
uniform int lightIndex;
// The light, fetched once here through the variant's path and handed to the fragments: lavapipe
// (zink) crashed fetching it from the UBO block array in the fragment stage.
flat out vec4 vLightPositionRadius;
flat out vec4 vLightColourIntensity;

void main() {
    PointLight light = lightAt(lightIndex);
    vLightPositionRadius = light.positionRadius;
    vLightColourIntensity = light.colourIntensity;
    vec3 centre = light.positionRadius.xyz;
#if defined(MIRRORED)
    centre.y = 2.0 * (frame.water.x - frame.cameraPosition.y) - centre.y;
#endif
    gl_Position = frame.viewProjection * vec4(centre + unitSpherePosition * light.positionRadius.w, 1.0);
}
