// The program variant table. Shader files are shared; variants differ only by #define.
#include "render/shader_variants.h"

#include "debug/debug_views.h"
#include "render/light_paths.h"

namespace oasis {
namespace {

std::vector<ProgramVariant> buildVariants() {
    std::vector<ProgramVariant> variants = {
        {"terrain.gbuffer", "terrain.vert", "terrain.frag", {"OUTPUT_GBUFFER"}},
        {"terrain.gbuffer.mirrored", "terrain.vert", "terrain.frag", {"OUTPUT_GBUFFER", "MIRRORED"}},
        {"vegetation.gbuffer", "vegetation.vert", "vegetation.frag", {"OUTPUT_GBUFFER"}},
        {"vegetation.gbuffer.mirrored", "vegetation.vert", "vegetation.frag", {"OUTPUT_GBUFFER", "MIRRORED"}},
        {"sky.forward", "fullscreen.vert", "sky.frag", {"FULLSCREEN_AT_FAR_PLANE"}},
        {"sky.forward.mirrored", "fullscreen.vert", "sky.frag", {"FULLSCREEN_AT_FAR_PLANE", "MIRRORED"}},
        {"lighting", "fullscreen.vert", "lighting.frag", {}},
        {"lighting.mirrored", "fullscreen.vert", "lighting.frag", {"MIRRORED"}},
        {"gbuffer.clear", "fullscreen.vert", "gbuffer_clear.frag", {"FULLSCREEN_AT_FAR_PLANE"}},
        {"water.mask", "water.vert", "water_mask.frag", {}},
        {"water.composite", "water.vert", "water_composite.frag", {}},
        {"tonemap", "fullscreen.vert", "tonemap.frag", {}},
        {"present", "fullscreen.vert", "debug_view.frag", {"VIEW_COLOUR"}},
        {"probe.height", "fullscreen.vert", "height_probe.frag", {}},
        {"floor.write", "fullscreen.vert", "floor.frag", {"FLOOR_WRITE"}},
        {"floor.read", "fullscreen.vert", "floor.frag", {"FLOOR_READ"}},
        {"plant.atlas", "plant_atlas.vert", "plant_atlas.frag", {}},
        // The three passes of the parallel turtle interpretation (src/render/plant_interpreter.h).
        {"lsystem.local", "", "", {"PASS_LOCAL_TRANSFORMS"}, "lsystem_interpret.comp"},
        {"lsystem.compose", "", "", {"PASS_COMPOSE_ROUND"}, "lsystem_interpret.comp"},
        {"lsystem.segments", "", "", {"PASS_EMIT_SEGMENTS"}, "lsystem_interpret.comp"},
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
        variants.push_back({"vegetation.forward.mirrored" + suffix, "vegetation.vert", "vegetation.frag",
                            {"OUTPUT_FORWARD", "MIRRORED", define}});
        variants.push_back({"light.mark" + suffix, "light_volume.vert", "light_volume.frag", {"MARK_ONLY", define}});
        variants.push_back({"light.mark.mirrored" + suffix, "light_volume.vert", "light_volume.frag",
                            {"MARK_ONLY", "MIRRORED", define}});
        variants.push_back({"light.shade" + suffix, "light_volume.vert", "light_volume.frag", {define}});
        variants.push_back({"light.shade.mirrored" + suffix, "light_volume.vert", "light_volume.frag",
                            {"MIRRORED", define}});
    }
    for (const DebugView& view : debugViews())
        variants.push_back({debugProgramName(view), "fullscreen.vert", "debug_view.frag", {view.remapDefine}});
    return variants;
}

}  // namespace

const std::vector<ProgramVariant>& programVariants() {
    static const std::vector<ProgramVariant> variants = buildVariants();
    return variants;
}

const ProgramVariant* findProgramVariant(const std::string& name) {
    for (const ProgramVariant& variant : programVariants())
        if (variant.name == name) return &variant;
    return nullptr;
}

}  // namespace oasis
