// The debug view table.
#include "debug/debug_views.h"

#include <algorithm>

#include "render/shader_variants.h"

namespace oasis {
namespace {

// The G-buffer as gbufferSurfaceShownAt and readGBuffer decode it: every target (gbufferPixelAt
// sizes the view by Info).
const std::vector<Resource> kGBuffer = {Target::Albedo, Target::Normal, Target::Position, Target::Info};
std::vector<Resource> gbufferAnd(std::initializer_list<Resource> more) {
    std::vector<Resource> reads = kGBuffer;
    reads.insert(reads.end(), more);
    return reads;
}

const std::vector<DebugView> kViews = {
    {"final", ViewSource::Final, "VIEW_COLOUR", "the lit frame as displayed",
     {"red", "green", "blue", "alpha"}, LegendScale::None, {Target::Final}},
    {"albedo", ViewSource::Albedo, "VIEW_ALBEDO", "material colour, gamma-encoded; black where nothing was drawn (sky)",
     {"linear red", "linear green", "linear blue", "specular intensity"}, LegendScale::None, kGBuffer},
    {"normal", ViewSource::Normal, "VIEW_NORMAL", "world normal xyz as rgb = 0.5 + 0.5 n",
     {"x", "y", "z", "length"}, LegendScale::None, kGBuffer},
    {"position", ViewSource::Position, "VIEW_POSITION",
     "camera-relative position, signed log scale to the view distance (grey = camera)",
     {"x", "y", "z", "distance"}, LegendScale::SignedLog, {Target::Position, Target::Info}},
    {"info", ViewSource::Info, "VIEW_INFO",
     "red specular power (0..64), green specular intensity (0..0.25), blue flags: 0.8 sky, else 0.5 reflected + 0.25 plant",
     {"specular power", "specular intensity", "flag bits"}, LegendScale::InfoFlags, kGBuffer},
    {"depth", ViewSource::Depth, "VIEW_DEPTH", "eye distance, log scale near to far; black = cleared",
     {"eye distance", "window depth"}, LegendScale::DepthRamp, {Target::DepthStencil}},
    {"stencil", ViewSource::Stencil, "VIEW_STENCIL",
     "one colour per stencil value: black 0 nothing, amber 1 terrain, blue 2 water, green 3 plants",
     {"stencil value"}, LegendScale::StencilSwatches, {Target::DepthStencil}},
    {"reflection", ViewSource::Reflection, "VIEW_RADIANCE",
     "the mirrored scene alone, tone-mapped; black outside the water or with reflections off",
     {"linear red", "linear green", "linear blue", "alpha"}, LegendScale::None, {Target::Reflection, Target::DepthStencil}},
    {"radiance", ViewSource::Radiance, "VIEW_HDR",
     "linear light before tone mapping (Radiance) times 2^exposure, gamma 2.2, clipped at 1: no tone curve",
     {"linear red", "linear green", "linear blue", "alpha"}, LegendScale::None, {Target::Radiance}},
    {"reflection-raw", ViewSource::Reflection, "VIEW_HDR",
     "the mirrored scene's linear light as stored (Reflection) times 2^exposure, gamma 2.2, clipped at 1",
     {"linear red", "linear green", "linear blue", "alpha"}, LegendScale::None, {Target::Reflection, Target::DepthStencil}},
    {"vegetation", ViewSource::Vegetation, "VIEW_VEGETATION",
     "the plants alone: the lit frame where a plant billboard is the nearest surface, black elsewhere",
     {"red", "green", "blue"}, LegendScale::None, gbufferAnd({Target::Final})},
    {"atlas", ViewSource::PlantAtlas, "VIEW_COLOUR",
     "the plant atlas, stretched to the view: a cell per L-system variant, brown base to green tips, on black",
     {"red", "green", "blue", "coverage"}, LegendScale::None, {}},
    {"light-volumes", ViewSource::Position, "VIEW_LIGHT_VOLUMES",
     "how many point lights reach each surface: dark grey 0, blue 1, green 2, yellow 4, red 8, white 16+; black sky",
     {"lights reaching", "lights in the list"}, LegendScale::LightHeat, kGBuffer},
    {"shadow", ViewSource::Position, "VIEW_SHADOW",
     "the sun's shadow: a hue per cascade (red, green, blue, yellow from the nearest), dark where shadowed; grey where "
     "no cascade reaches, black sky; all grey with shadows off or the sun down",
     {"lit fraction", "cascade (-1 none)", "sun facing (n.l)"}, LegendScale::None, gbufferAnd({Buffer::ShadowMaps})},
};


}  // namespace

const std::vector<DebugView>& debugViews() { return kViews; }

const DebugView* findDebugView(const std::string& name) {
    for (const DebugView& view : kViews)
        if (view.name == name) return &view;
    return nullptr;
}

std::string debugViewNames() {
    std::string names;
    for (const DebugView& view : kViews) names += view.name + ", ";
    return names + kOverviewName;
}

std::vector<Resource> viewReads(const DebugView& view, const GBufferLayout& layout) {
    std::vector<Resource> reads;
    for (Resource read : view.reads) {
        if (read == Resource(Target::Position) && !layout.stores(Target::Position)) read = Target::DepthStencil;
        if (std::find(reads.begin(), reads.end(), read) == reads.end()) reads.push_back(read);
    }
    return reads;
}

bool readsGBuffer(const DebugView& view) {
    return view.source == ViewSource::Albedo || view.source == ViewSource::Normal ||
           view.source == ViewSource::Position || view.source == ViewSource::Info ||
           view.source == ViewSource::Vegetation;
}

bool readsSceneSurfaces(const DebugView& view) {
    return readsGBuffer(view) || view.source == ViewSource::Depth || view.source == ViewSource::Stencil;
}

std::string waterNote(const DebugView& view, const std::string& surfaces) {
    switch (view.source) {
        case ViewSource::Final:
        case ViewSource::Radiance:
            return "under the water: the water as shaded (the lakebed seen through it plus the reflection)";
        case ViewSource::Reflection:
            return "inside the water: the mirrored scene as shaded, before the water composite";
        case ViewSource::Stencil:
            return "under the water: 2, the water's mark (the same whichever scene the other views show)";
        case ViewSource::PlantAtlas:
            return "";
        default:
            return "under the water: " + surfaces;
    }
}

std::string debugProgramName(const DebugView& view) { return "debug." + view.name; }
std::string debugValuesProgramName(const DebugView& view) { return "debug.values." + view.name; }

void registerDebugViewPrograms() {
    static const bool registered = [] {
        std::vector<ProgramVariant> variants;
        for (const DebugView& view : debugViews()) {
            variants.push_back({debugProgramName(view), "fullscreen.vert", "debug_view.frag", {view.remapDefine}});
            variants.push_back({debugValuesProgramName(view), "fullscreen.vert", "debug_view.frag",
                                {view.remapDefine, "VIEW_VALUES"}});
        }
        addProgramVariants(variants);
        return true;
    }();
    (void)registered;
}

}  // namespace oasis
