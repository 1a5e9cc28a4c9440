// The debug view table.
#include "debug/debug_views.h"

namespace oasis {
namespace {

const std::vector<DebugView> kViews = {
    {"final", ViewSource::Final, "VIEW_COLOUR", "the lit frame as displayed"},
    {"albedo", ViewSource::Albedo, "VIEW_ALBEDO", "material colour, gamma-encoded; black where nothing was drawn (sky)"},
    {"normal", ViewSource::Normal, "VIEW_NORMAL", "world normal xyz as rgb = 0.5 + 0.5 n"},
    {"position", ViewSource::Position, "VIEW_POSITION",
     "camera-relative position, signed log scale to the view distance (grey = camera)"},
    {"info", ViewSource::Info, "VIEW_INFO",
     "red specular power (0..64), green specular intensity (0..0.25), blue flags: 0.8 sky, else 0.5 reflected + 0.25 plant"},
    {"depth", ViewSource::Depth, "VIEW_DEPTH", "eye distance, log scale near to far; black = cleared"},
    {"stencil", ViewSource::Stencil, "VIEW_STENCIL",
     "one colour per stencil value: black 0 nothing, amber 1 terrain, blue 2 water, green 3 plants"},
    {"reflection", ViewSource::Reflection, "VIEW_RADIANCE",
     "the mirrored scene alone, tone-mapped; black outside the water or with reflections off"},
    {"radiance", ViewSource::Radiance, "VIEW_HDR",
     "linear light before tone mapping (Radiance) times 2^exposure, gamma 2.2, clipped at 1: no tone curve"},
    {"reflection-raw", ViewSource::Reflection, "VIEW_HDR",
     "the mirrored scene's linear light as stored (Reflection) times 2^exposure, gamma 2.2, clipped at 1"},
    {"vegetation", ViewSource::Vegetation, "VIEW_VEGETATION",
     "the plants alone: the lit frame where a plant billboard is the nearest surface, black elsewhere"},
    {"atlas", ViewSource::PlantAtlas, "VIEW_COLOUR",
     "the plant atlas, stretched to the view: a cell per L-system variant, brown base to green tips, on black"},
    {"light-volumes", ViewSource::Position, "VIEW_LIGHT_VOLUMES",
     "how many point lights reach each surface: dark grey 0, blue 1, green 2, yellow 4, red 8, white 16+; black sky"},
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

bool readsGBuffer(const DebugView& view) {
    return view.source == ViewSource::Albedo || view.source == ViewSource::Normal ||
           view.source == ViewSource::Position || view.source == ViewSource::Info ||
           view.source == ViewSource::Vegetation;
}

std::string debugProgramName(const DebugView& view) { return "debug." + view.name; }

}  // namespace oasis
