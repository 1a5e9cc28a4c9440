// Runs the shading record (shaders/probe_shading.frag) at one pixel over the surfaces the frame
// shaded there (the G-buffer, or a forward frame's drawn again unrounded) and names what it
// recorded: one row of kTerms per slot of common/shading_terms.glsl.
#include "frame/shading_probe.h"

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "common/shading_terms.glsl"
#include "common/shared_constants.glsl"
#include "context/gl_context.h"
#include "frame/pixel_probe.h"
#include "frame/renderer.h"
#include "passes/pass.h"
#include "render/float_readback.h"
#include "render/gbuffer_layout.h"
#include "io/json_text.h"
#include "render/light_paths.h"
#include "render/texture_units.h"

namespace oasis {
namespace {

enum class Group { Surface, Sky, Water, ToneMap };

struct TermRow {
    int slot;
    const char* name;
    int components;
    Group group;
    const char* unit;
};

constexpr const char* kRadiance = "linear radiance, RGB";
constexpr TermRow kTerms[] = {
    {OASIS_TERM_TO_SUN, "to_sun", 3, Group::Surface, "unit vector towards the sun, world"},
    {OASIS_TERM_SUN_RADIANCE, "sun_radiance", 3, Group::Surface, kRadiance},
    {OASIS_TERM_TO_CAMERA, "to_camera", 3, Group::Surface, "unit vector surface to (mirrored) camera, world"},
    {OASIS_TERM_NORMAL, "normal", 4, Group::Surface, "unit normal xyz, world; N.L cosine"},
    {OASIS_TERM_SHADOW, "shadow", 2, Group::Surface, "sun visibility 0..1; cascade (-1 none)"},
    {OASIS_TERM_SUN_AT_SURFACE, "sun_at_surface", 3, Group::Surface, "linear radiance, RGB (sun x visibility)"},
    {OASIS_TERM_SPECULAR_LOBE, "specular_lobe", 4, Group::Surface,
     "max(N.L,0); normalisation (p+8)/(8 pi); N.H; specular factor"},
    {OASIS_TERM_AMBIENT, "ambient", 3, Group::Surface, "linear radiance, RGB (hemisphere sky/ground)"},
    {OASIS_TERM_ALBEDO, "albedo", 4, Group::Surface, "linear reflectance RGB; specular power"},
    {OASIS_TERM_DIFFUSE_PART, "diffuse_part", 3, Group::Surface, "linear radiance, RGB (albedo x sun x max(N.L,0))"},
    {OASIS_TERM_AMBIENT_PART, "ambient_part", 3, Group::Surface, "linear radiance, RGB (albedo x ambient)"},
    {OASIS_TERM_SPECULAR_PART, "specular_part", 3, Group::Surface, "linear radiance, RGB (sun x specular factor)"},
    {OASIS_TERM_LIT, "lit", 3, Group::Surface, "linear radiance, RGB (the three parts, at the surface)"},
    {OASIS_TERM_WATER_CROSSED, "water_crossed", 4, Group::Surface, "transmittance RGB 0..1; length under water, world units"},
    {OASIS_TERM_WATER_SCATTER, "water_scatter", 3, Group::Surface, kRadiance},
    {OASIS_TERM_AFTER_WATER, "after_water", 3, Group::Surface,
     "linear radiance, RGB (lit x transmittance + scatter x (1 - transmittance))"},
    {OASIS_TERM_FOG, "fog", 2, Group::Surface, "fog weight 0..1; eye distance, world units"},
    {OASIS_TERM_FOG_COLOUR, "fog_colour", 3, Group::Surface, kRadiance},
    {OASIS_TERM_SURFACE, "surface", 3, Group::Surface, "linear radiance, RGB (mix(after_water, fog_colour, fog))"},
    {OASIS_TERM_LIGHTS, "lights", 4, Group::Surface, "linear radiance RGB, carried to the eye; lights reaching"},
    {OASIS_TERM_SKY, "sky", 3, Group::Sky, "linear radiance, RGB (along the view ray)"},
    {OASIS_TERM_WATER_NORMAL, "water_normal", 4, Group::Water, "rippled unit normal xyz; cos(view, normal)"},
    {OASIS_TERM_FRESNEL, "fresnel", 4, Group::Water, "Fresnel weight F; glint factor; fog weight; F0"},
    {OASIS_TERM_REFLECTED, "reflected", 3, Group::Water, "linear radiance, RGB (Reflection, or the sky alone)"},
    {OASIS_TERM_UNDER, "under", 3, Group::Water, "linear radiance, RGB (the direct scene's radiance)"},
    {OASIS_TERM_WATER_RESULT, "result", 4, Group::Water,
     "linear radiance RGB: (F reflected + glint sun)(1 - fog) + (1 - F(1 - fog)) under; alpha F(1 - fog)"},
    {OASIS_TERM_TONE_MAP, "input", 4, Group::ToneMap, "linear radiance RGB as Radiance stores it (half floats); exposure"},
    {OASIS_TERM_DISPLAY, "output", 3, Group::ToneMap, "display colour 0..1 (x 255 = Final)"},
};

using Slots = std::vector<float>;  // OASIS_SHADING_TERMS RGBA texels

// `surfaces`: where the record reads the surfaces (the G-buffer, or a forward frame's exact ones);
// Reflection and Radiance are always the frame's.
Slots drawRecord(Renderer& renderer, const FrameTargets& surfaces, const std::string& variant, int glX, int glY,
                 bool water, bool mirrored, const glm::vec3& lights) {
    const FrameTargets& targets = renderer.targets();
    FloatReadback values;
    values.bindForDrawing(OASIS_SHADING_TERMS, 1);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    bindGBufferInputs(surfaces);
    renderer.parts().shadowMaps.bind();
    glActiveTexture(GL_TEXTURE0 + kUnitSource);
    glBindTexture(GL_TEXTURE_2D, targets.texture(Target::Reflection));
    glActiveTexture(GL_TEXTURE0 + kUnitRadiance);
    glBindTexture(GL_TEXTURE_2D, targets.texture(Target::Radiance));
    GLuint program = renderer.parts().shaders.program(surfaces.layout().program(variant));
    glUseProgram(program);
    glUniform2i(glGetUniformLocation(program, "probePixel"), glX, glY);
    glUniform1i(glGetUniformLocation(program, "probeWater"), water ? 1 : 0);
    glUniform1i(glGetUniformLocation(program, "probeMirrored"), mirrored ? 1 : 0);
    glUniform3f(glGetUniformLocation(program, "probeLights"), lights.r, lights.g, lights.b);
    renderer.parts().geometry.drawFullscreenTriangle();
    glActiveTexture(GL_TEXTURE0);
    return values.read();
}

// lavapipe (under zink; Mesa 22.3.6) crashes running the lights' record through the UBO path: "stack
// smashing detected" or a SIGSEGV in libvulkan_lvp.so's worker thread, even with no lights. The
// record would be the frame's own light code on another path, so it is refused, with the way round.
void refuseLavapipeUboRecord(LightsPath path) {
    // The context's own renderer string, as the check's driver report reads it (context/gl_context.h).
    const std::string renderer = queryContextInfo().renderer;
    bool lavapipe = renderer.find("zink") != std::string::npos &&
                    (renderer.find("llvmpipe") != std::string::npos || renderer.find("lavapipe") != std::string::npos);
    if (lavapipe && path == LightsPath::Ubo)
        throw std::runtime_error("probe --shading: " + renderer +
                                 " crashes running the lights' record through the UBO light path (a lavapipe bug); "
                                 "--lights-path ssbo records them on this driver");
}

// The point lights' terms first (their own draw), then everything else with their sum.
Slots recordShading(Renderer& renderer, const FrameTargets& surfaces, int glX, int glY, bool water, bool mirrored) {
    refuseLavapipeUboRecord(renderer.lastFrame().setup.lightsPath);
    std::string lightsVariant = "probe.shading.lights" + lightsVariantSuffix(renderer.lastFrame().setup.lightsPath);
    Slots lights = drawRecord(renderer, surfaces, lightsVariant, glX, glY, water, mirrored, glm::vec3(0.0f));
    const float* sum = &lights[OASIS_TERM_LIGHTS * 4];
    Slots slots = drawRecord(renderer, surfaces, "probe.shading", glX, glY, water, mirrored,
                             glm::vec3(sum[0], sum[1], sum[2]));
    slots[OASIS_TERM_LIGHTS * 4 + 3] = sum[3];
    for (int c = 0; c < 4; ++c) slots[size_t(OASIS_TERM_LIGHTS * 4 + c)] = sum[c];
    for (int k = 0; k < OASIS_TERM_LIGHT_SLOTS * 4; ++k)
        slots[size_t(OASIS_TERM_FIRST_LIGHT * 4 + k)] = lights[size_t(OASIS_TERM_FIRST_LIGHT * 4 + k)];
    return slots;
}

ShadingTerm termAt(const Slots& slots, const TermRow& row, const std::string& name) {
    ShadingTerm term{name, row.unit, {}};
    for (int c = 0; c < row.components; ++c) term.values.push_back(slots[size_t(row.slot * 4 + c)]);
    return term;
}

// The surface (or sky) shading of one fill: every surface term and each light's share, or the sky.
ShadedSurface surfaceTerms(const Slots& slots, const std::string& name, const std::string& what) {
    ShadedSurface surface{name, what, {}};
    bool sky = slots[OASIS_TERM_RADIANCE * 4 + 3] > 0.5f;
    for (const TermRow& row : kTerms)
        if (row.group == (sky ? Group::Sky : Group::Surface)) surface.terms.push_back(termAt(slots, row, row.name));
    if (!sky) {
        int reaching = int(slots[OASIS_TERM_LIGHTS * 4 + 3]);
        for (int k = 0; k < std::min(reaching, OASIS_TERM_LIGHT_SLOTS); ++k) {
            int slot = OASIS_TERM_FIRST_LIGHT + k;
            TermRow row{slot, "", 3, Group::Surface, "linear radiance, RGB, carried to the eye"};
            surface.terms.push_back(
                termAt(slots, row, "light " + std::to_string(int(slots[size_t(slot * 4 + 3)]))));
        }
    }
    TermRow radiance{OASIS_TERM_RADIANCE, "radiance", 3, Group::Surface,
                     sky ? kRadiance : "linear radiance, RGB (surface + lights)"};
    surface.terms.push_back(termAt(slots, radiance, "radiance"));
    return surface;
}

ShadedSurface groupTerms(const Slots& slots, Group group, const std::string& name, const std::string& what) {
    ShadedSurface surface{name, what, {}};
    for (const TermRow& row : kTerms)
        if (row.group == group) surface.terms.push_back(termAt(slots, row, row.name));
    return surface;
}

// The surfaces the frame shaded at the pixel, `scene` under the water. Deferred: its G-buffer,
// which its lighting read; a forward frame stopped early: the views' fill of the steps it ran
// (frame/view_fill.h), as the other views show it. A whole forward frame shaded
// each surface as its fragment built it and stored none: the views' G-buffer would round it (8-bit
// albedo, compact normals: up to 6 % off the frame), so the same surface shaders (terrain.frag,
// vegetation.frag, the G-buffer variants of the forward ones: the same Surface, only emitted
// elsewhere) draw it again into targets of the "full" layout, every value a 32-bit float.
class ShadedSurfaces {
public:
    explicit ShadedSurfaces(Renderer& renderer) : renderer_(renderer) {
        const FrameTargets& frame = renderer.targets();
        if (renderer.pipeline() == PipelineKind::Forward && renderer.lastFrame().setup.runsToEnd)
            exact_ = std::make_unique<FrameTargets>(*findGBufferLayout("full"), frame.depth(), frame.width(),
                                                    frame.height(), "probe --shading: forward surfaces");
    }
    const FrameTargets& fill(WaterScene scene) {
        if (exact_) {
            renderer_.views().fillExactSurfaces(*exact_, scene);
            return *exact_;
        }
        renderer_.views().setWaterScene(scene);
        renderer_.views().ensureGBuffer();
        return renderer_.targets();
    }

private:
    Renderer& renderer_;
    std::unique_ptr<FrameTargets> exact_;
};

}  // namespace

const ShadingTerm* ShadedSurface::find(const std::string& termName) const {
    for (const ShadingTerm& term : terms)
        if (term.name == termName) return &term;
    return nullptr;
}

std::vector<ShadedSurface> probeShading(Renderer& renderer, const PixelProbe& probe) {
    const int glX = probe.x, glY = renderer.targets().height() - 1 - probe.y;
    const bool water = (probe.stencil & 0x7f) == kStencilWater;
    const bool mirrored = water && renderer.lastFrame().setup.reflectionsActive;
    const WaterScene viewScene = renderer.views().waterScene();
    std::vector<ShadedSurface> shading;

    ShadedSurfaces surfaces(renderer);
    Slots direct = recordShading(renderer, surfaces.fill(WaterScene::Direct), glX, glY, water, false);
    shading.push_back(surfaceTerms(direct, "direct",
                                   water ? "under the water: the direct scene's surface (the frame's Radiance before the composite)"
                                         : "the surface seen here (the frame's Radiance)"));
    if (mirrored) {
        Slots reflected = recordShading(renderer, surfaces.fill(WaterScene::Mirrored), glX, glY, false, true);
        std::string what = "what the water reflects: the mirrored scene (the frame's Reflection";
        what += renderer.lastFrame().setup.reflectionDivisor > 1 ? ", drawn there at a reduced resolution and upsampled)" : ")";
        shading.push_back(surfaceTerms(reflected, "mirrored", what));
    }
    if (water)
        shading.push_back(groupTerms(direct, Group::Water, "water",
                                     "the water's surface over the direct scene (the frame's Radiance after the composite)"));
    shading.push_back(groupTerms(direct, Group::ToneMap, "tone_map", "Radiance to the displayed colour (Final)"));
    renderer.views().setWaterScene(viewScene);
    return shading;
}

std::string shadingText(const std::vector<ShadedSurface>& shading) {
    std::string text = "shading (recorded by the frame's lighting GLSL at this pixel):\n";
    for (const ShadedSurface& surface : shading) {
        text += "  " + surface.name + ": " + surface.what + "\n";
        for (const ShadingTerm& term : surface.terms) {
            char line[160];
            std::snprintf(line, sizeof line, "    %-15s %-44s ", term.name.c_str(), numberList(term.values, " ", "%.6g").c_str());
            text += line + term.unit + "\n";
        }
    }
    return text;
}

std::string shadingJson(const std::vector<ShadedSurface>& shading) {
    std::string json = "{";
    for (size_t s = 0; s < shading.size(); ++s) {
        const ShadedSurface& surface = shading[s];
        json += (s ? ", " : "") + jsonString(surface.name) + ": {\"what\": " + jsonString(surface.what) + ", \"terms\": {";
        for (size_t t = 0; t < surface.terms.size(); ++t) {
            const ShadingTerm& term = surface.terms[t];
            json += (t ? ", " : "") + jsonString(term.name) + ": {\"value\": [" + numberList(term.values, ", ", "%.6g", true) +
                    "], \"unit\": " + jsonString(term.unit) + "}";
        }
        json += "}}";
    }
    return json + "}";
}

}  // namespace oasis
