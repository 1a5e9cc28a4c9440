// `oasis probe --shading`: how one pixel was shaded, term by term, recorded on the GPU by the
// frame's own lighting GLSL (shaders/probe_shading.frag's SHADING_RECORD variant): the sun, the eye,
// shadow, ambient, the diffuse/specular/ambient parts, water crossed, fog, each point light's
// share, the sky; at water pixels the mirrored scene and the water's surface (Fresnel, glint,
// what lies under it); and the tone map's input and output.
#pragma once
#include <string>
#include <vector>

namespace oasis {

class Renderer;
struct PixelProbe;

struct ShadingTerm {
    std::string name;            // "diffuse_part", "fresnel", "light 3" ...
    std::string unit;            // what the numbers are, in order
    std::vector<double> values;
};

// One shading evaluated at the pixel: "direct" (the surface or sky seen there; at water, what lies
// under it), "mirrored" (the reflected scene, water pixels with reflections), "water" (its surface
// over the direct scene), "tone_map".
struct ShadedSurface {
    std::string name;
    std::string what;            // one line for people: which surface, and how it relates to the frame's targets
    std::vector<ShadingTerm> terms;
    const ShadingTerm* find(const std::string& termName) const;
};

// The pixel's shading after the last frame (`probe` was taken of the same frame: its stencil says
// whether the pixel shows water). Deferred: fills the G-buffer with the direct scene, and the
// mirrored one at water pixels (frame/view_fill.h), leaving the views' water scene as it was.
// Forward (a whole frame): the same fills into float targets of its own, so the record shades the
// surfaces the forward shaders built, unrounded by the G-buffer's encoding; the G-buffer is untouched.
std::vector<ShadedSurface> probeShading(Renderer& renderer, const PixelProbe& probe);

std::string shadingText(const std::vector<ShadedSurface>& shading);  // lines for people
std::string shadingJson(const std::vector<ShadedSurface>& shading);  // the value of the key "shading"

}  // namespace oasis
