// The program variant table. Shader files are shared; variants differ only by #define.
#include "render/shader_variants.h"

#include <algorithm>

#include "render/gbuffer_layout.h"
#include "render/light_paths.h"

namespace oasis {
namespace {

// Programs that write or read the G-buffer, so need a variant per encoding: the surface writers,
// the clear, the floor, the lighting and light-volume shading, and the debug views (debug_view.frag,
// also the present pass's).
bool touchesGBuffer(const ProgramVariant& variant) {
    const auto& d = variant.defines;
    bool writes = std::find(d.begin(), d.end(), "OUTPUT_GBUFFER") != d.end();
    if (variant.computeFile == "light_tiles.comp") return true;  // reads the surfaces' positions
    const std::string readers[] = {"lighting.frag", "light_volume.frag", "gbuffer_clear.frag", "floor.frag",
                                   "debug_view.frag", "gbuffer_positions.frag", "probe.frag",
                                   "probe_shading.frag"};
    bool marksOnly = std::find(d.begin(), d.end(), "MARK_ONLY") != d.end();
    return writes || (!marksOnly && std::find(std::begin(readers), std::end(readers), variant.fragmentFile) !=
                                        std::end(readers));
}

// The variants with, after them, their variant per encoding other than the plain one: "<name>.compact"
// with GBUFFER_COMPACT, and so on, for each variant that touches the G-buffer.
std::vector<ProgramVariant> withEncodings(std::vector<ProgramVariant> variants) {
    std::vector<GBufferEncoding> encodings;
    for (const GBufferLayout& layout : gbufferLayouts())
        if (*gbufferEncodingDefine(layout.encoding) &&
            std::find(encodings.begin(), encodings.end(), layout.encoding) == encodings.end())
            encodings.push_back(layout.encoding);
    size_t plain = variants.size();
    for (GBufferEncoding encoding : encodings)
        for (size_t i = 0; i < plain; ++i) {
            if (!touchesGBuffer(variants[i])) continue;
            ProgramVariant variant = variants[i];
            variant.name += gbufferEncodingSuffix(encoding);
            variant.defines.push_back(gbufferEncodingDefine(encoding));
            variants.push_back(variant);
        }
    return variants;
}

std::vector<ProgramVariant> fixedVariants() {
    std::vector<ProgramVariant> variants = {
        // Each grid vertex's place and height, once a frame, for every terrain draw after it
        // (passes/terrain_heights_pass.h): captured by transform feedback, nothing rasterised.
        {"terrain.heights", "terrain.vert", "terrain.frag", {"OUTPUT_HEIGHTS"}, "", {"heightsOffset", "heightsHeight"}},
        {"terrain.gbuffer", "terrain.vert", "terrain.frag", {"OUTPUT_GBUFFER"}},
        {"terrain.gbuffer.mirrored", "terrain.vert", "terrain.frag", {"OUTPUT_GBUFFER", "MIRRORED"}},
        {"vegetation.gbuffer", "vegetation.vert", "vegetation.frag", {"OUTPUT_GBUFFER"}},
        {"vegetation.gbuffer.mirrored", "vegetation.vert", "vegetation.frag", {"OUTPUT_GBUFFER", "MIRRORED"}},
        // The sun's shadow casters (passes/shadow_pass.h): depth only, plants alpha-tested as drawn.
        {"terrain.shadow", "terrain.vert", "terrain.frag", {"OUTPUT_SHADOW"}},
        {"vegetation.shadow", "vegetation.vert", "vegetation.frag", {"OUTPUT_SHADOW"}},
        {"sky.forward", "fullscreen.vert", "sky.frag", {"FULLSCREEN_AT_FAR_PLANE"}},
        {"sky.forward.mirrored", "fullscreen.vert", "sky.frag", {"FULLSCREEN_AT_FAR_PLANE", "MIRRORED"}},
        {"lighting", "fullscreen.vert", "lighting.frag", {"FULLSCREEN_AT_FAR_PLANE"}},
        {"lighting.mirrored", "fullscreen.vert", "lighting.frag", {"FULLSCREEN_AT_FAR_PLANE", "MIRRORED"}},
        {"gbuffer.clear", "fullscreen.vert", "gbuffer_clear.frag", {"FULLSCREEN_AT_FAR_PLANE", "WATER_BOUNDED"}},
        {"water.mask", "water.vert", "water_mask.frag", {}},
        {"water.mask.plane", "water.vert", "water_mask.frag", {"WATER_PLANE_ONLY"}},
        {"reflection.upsample", "fullscreen.vert", "reflection_upsample.frag", {"WATER_BOUNDED"}},
        {"water.composite", "water.vert", "water_composite.frag", {}},
        // The water without depth clamp: a full-screen triangle finding the plane per fragment
        // (common/water_fragment.glsl), where the grid would lose the water nearer than the near plane.
        {"water.mask.fullscreen", "fullscreen.vert", "water_mask.frag", {"WATER_FULLSCREEN"}},
        {"water.mask.plane.fullscreen", "fullscreen.vert", "water_mask.frag", {"WATER_PLANE_ONLY", "WATER_FULLSCREEN"}},
        {"water.composite.fullscreen", "fullscreen.vert", "water_composite.frag", {"WATER_FULLSCREEN"}},
        {"water.composite.tonemapped.fullscreen", "fullscreen.vert", "water_composite.frag",
         {"TONE_MAP_FUSED", "WATER_FULLSCREEN"}},
        // The tone map fused into the pass that writes a pixel's colour last (docs/architecture.md: the
        // full-screen passes): ".tonemapped" variants also write Final; "tonemap" is the separate pass.
        {"water.composite.tonemapped", "water.vert", "water_composite.frag", {"TONE_MAP_FUSED"}},
        {"lighting.tonemapped", "fullscreen.vert", "lighting.frag", {"FULLSCREEN_AT_FAR_PLANE", "TONE_MAP_FUSED"}},
        {"sky.forward.tonemapped", "fullscreen.vert", "sky.frag", {"FULLSCREEN_AT_FAR_PLANE", "TONE_MAP_FUSED"}},
        {"tonemap", "fullscreen.vert", "tonemap.frag", {}},
        {"present", "fullscreen.vert", "debug_view.frag", {"VIEW_COLOUR"}},
        {"probe.height", "fullscreen.vert", "height_probe.frag", {}},
        {"gbuffer.positions", "fullscreen.vert", "gbuffer_positions.frag", {}},
        {"probe.pixel", "fullscreen.vert", "probe.frag", {}},
        // Depth and stencil read by drawing where glReadPixels cannot (render/depth_stencil_readback.h).
        {"readback.depth", "fullscreen.vert", "depth_stencil_read.frag", {"READ_DEPTH"}},
        {"readback.stencil", "fullscreen.vert", "depth_stencil_read.frag", {"READ_STENCIL_BIT"}},
        {"readback.shadow-layer", "fullscreen.vert", "depth_stencil_read.frag", {"READ_SHADOW_LAYER"}},
        // `probe --shading`: the lighting GLSL with its terms recorded (common/shading_terms.glsl).
        {"probe.shading", "fullscreen.vert", "probe_shading.frag", {"SHADING_RECORD"}},
        {"depth.copy", "fullscreen.vert", "depth_copy.frag", {}},
        {"depth.copy.mirrored", "fullscreen.vert", "depth_copy.frag", {"WATER_BOUNDED"}},
        {"floor.write", "fullscreen.vert", "floor.frag", {"FLOOR_WRITE"}},
        {"floor.read", "fullscreen.vert", "floor.frag", {"FLOOR_READ"}},
        {"plant.atlas", "plant_atlas.vert", "plant_atlas.frag", {}},
        // The three passes of the parallel turtle interpretation (src/render/plant_interpreter.h).
        {"lsystem.local", "", "", {"PASS_LOCAL_TRANSFORMS"}, "lsystem_interpret.comp"},
        {"lsystem.compose", "", "", {"PASS_COMPOSE_ROUND"}, "lsystem_interpret.comp"},
        {"lsystem.segments", "", "", {"PASS_EMIT_SEGMENTS"}, "lsystem_interpret.comp"},
        // The tiled light method (render/light_method.h): the per-tile light lists, then the
        // lighting pass adding each tile's lights. It needs SSBOs for its lists, so it reads the
        // lights from the storage block too whatever the light path (with the count from its own
        // block, which every driver compiles; the UBO block array cannot take a per-pixel index).
        {"light.tiles", "", "", {"LIGHTS_SSBO_COUNT"}, "light_tiles.comp"},
        {"light.tiles.mirrored", "", "", {"MIRRORED", "LIGHTS_SSBO_COUNT"}, "light_tiles.comp"},
        {"lighting.tiled", "fullscreen.vert", "lighting.frag", {"FULLSCREEN_AT_FAR_PLANE", "LIGHTS_TILED", "LIGHTS_SSBO_COUNT"}},
        {"lighting.mirrored.tiled", "fullscreen.vert", "lighting.frag",
         {"FULLSCREEN_AT_FAR_PLANE", "MIRRORED", "LIGHTS_TILED", "LIGHTS_SSBO_COUNT"}},
        {"lighting.tonemapped.tiled", "fullscreen.vert", "lighting.frag",
         {"FULLSCREEN_AT_FAR_PLANE", "TONE_MAP_FUSED", "LIGHTS_TILED", "LIGHTS_SSBO_COUNT"}},
    };
    // Point lights, once per light path (render/light_paths.h): the forward surfaces' light loop
    // (terrain and plants) and the deferred light volumes (stencil marking, then shading), direct
    // and mirrored.
    for (LightsPath path : {LightsPath::Ssbo, LightsPath::SsboCount, LightsPath::Ubo}) {
        std::string suffix = lightsVariantSuffix(path), define = lightsPathDefine(path);
        variants.push_back({"terrain.forward" + suffix, "terrain.vert", "terrain.frag", {"OUTPUT_FORWARD", define}});
        variants.push_back({"terrain.forward.mirrored" + suffix, "terrain.vert", "terrain.frag",
                            {"OUTPUT_FORWARD", "MIRRORED", define}});
        variants.push_back({"vegetation.forward" + suffix, "vegetation.vert", "vegetation.frag", {"OUTPUT_FORWARD", define}});
        variants.push_back({"terrain.forward.tonemapped" + suffix, "terrain.vert", "terrain.frag",
                            {"OUTPUT_FORWARD", "TONE_MAP_FUSED", define}});
        variants.push_back({"vegetation.forward.tonemapped" + suffix, "vegetation.vert", "vegetation.frag",
                            {"OUTPUT_FORWARD", "TONE_MAP_FUSED", define}});
        variants.push_back({"vegetation.forward.mirrored" + suffix, "vegetation.vert", "vegetation.frag",
                            {"OUTPUT_FORWARD", "MIRRORED", define}});
        variants.push_back({"light.mark" + suffix, "light_volume.vert", "light_volume.frag", {"MARK_ONLY", define}});
        variants.push_back({"light.mark.mirrored" + suffix, "light_volume.vert", "light_volume.frag",
                            {"MARK_ONLY", "MIRRORED", define}});
        variants.push_back({"light.shade" + suffix, "light_volume.vert", "light_volume.frag", {define}});
        variants.push_back({"light.shade.mirrored" + suffix, "light_volume.vert", "light_volume.frag",
                            {"MIRRORED", define}});
        // The light list as this path reads it, for the check's pass-by-pass search (lights_decode.frag).
        variants.push_back({"lights.decode" + suffix, "fullscreen.vert", "lights_decode.frag", {define}});
        // `probe --shading`'s point lights, read through the frame's own path (probe_shading.frag).
        variants.push_back({"probe.shading.lights" + suffix, "fullscreen.vert", "probe_shading.frag",
                            {"SHADING_RECORD", "SHADING_LIGHTS", define}});
    }
    return withEncodings(variants);
}

std::deque<ProgramVariant>& table() {
    static std::deque<ProgramVariant> variants = [] {
        std::vector<ProgramVariant> fixed = fixedVariants();
        return std::deque<ProgramVariant>(fixed.begin(), fixed.end());
    }();
    return variants;
}

}  // namespace

const std::deque<ProgramVariant>& programVariants() { return table(); }

void addProgramVariants(const std::vector<ProgramVariant>& variants) {
    for (ProgramVariant& variant : withEncodings(variants)) table().push_back(std::move(variant));
}

const ProgramVariant* findProgramVariant(const std::string& name) {
    for (const ProgramVariant& variant : programVariants())
        if (variant.name == name) return &variant;
    return nullptr;
}

}  // namespace oasis
