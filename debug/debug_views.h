// The debug views: one table (name, the target it shows, the shader remapping, what a person
// sees, the numbers behind it and the scale its legend draws). The CLI's --view, the window's keys
// and menu, the overview grid, the legends and the tests all read this table, so a new view is
// one entry here (plus its VIEW_* remapping in shaders/debug_view.frag if it needs a new one).
#pragma once
#include <string>
#include <vector>

#include "passes/pass.h"
#include "render/gbuffer_layout.h"

namespace oasis {

enum class ViewSource { Final, Albedo, Normal, Position, Info, Depth, Stencil, Radiance, Reflection, PlantAtlas, Vegetation };

// What the legend under a view image draws besides its text (debug/view_legend.h).
enum class LegendScale {
    None,         // colours are the picture itself (final, albedo, radiance)
    DepthRamp,    // the ramp of eye distance, log scale from the near to the far plane
    SignedLog,    // position: each axis on a signed log scale to the view distance
    LightHeat,    // light counts 0, 1, 2, 4, 8, 16+
    StencilSwatches,
    InfoFlags,    // the info view's channels and flag marks
    Grey,         // the view controls: a channel mapped linearly from a range to black..white
    DifferenceHeat,  // compare's difference.png: black, red, yellow, white at full scale
    LinearRamp,   // the encoding-error views: the depth view's ramp over a linear range
};

struct DebugView {
    std::string name;
    ViewSource source;
    std::string remapDefine;  // the VIEW_* define of shaders/debug_view.frag
    std::string legend;       // what the colours mean
    // The numbers behind each pixel (viewValue() in debug_view.frag), one name per channel r, g,
    // b, a that the view fills: what --channel may pick, the probe of a view, the range's unit.
    std::vector<std::string> values;
    LegendScale scale = LegendScale::None;
    // What its shader samples of the frame (debug_view.frag, common/gbuffer.glsl), Position
    // standing for the surface's position as the layout keeps it (viewReads): a frame drawn to
    // show this view alone is culled to what these need (FrameViews::setSink).
    std::vector<Resource> reads = {};
};

const std::vector<DebugView>& debugViews();
const DebugView* findDebugView(const std::string& name);
std::string debugViewNames();  // "final, albedo, ..., overview" for help and errors
inline const char* kOverviewName = "overview";

// The view's reads in `layout`: Position becomes the depth-stencil target where the layout
// rebuilds position from depth (compact, which also tells the sky by depth there).
std::vector<Resource> viewReads(const DebugView& view, const GBufferLayout& layout);

// True when the view reads a G-buffer colour target (which only the deferred pipeline fills).
bool readsGBuffer(const DebugView& view);
// True when the view reads the frame's surfaces (the G-buffer, depth or stencil), which the
// renderer fills with one water scene before the view (frame/view_fill.h).
bool readsSceneSurfaces(const DebugView& view);
// What the view shows at water pixels, one line for its legend and the panel; `surfaces` is what
// the G-buffer and depth hold there (FrameViews::scene().description). "" for the atlas.
std::string waterNote(const DebugView& view, const std::string& surfaces);
std::string debugProgramName(const DebugView& view);        // "debug.<name>"
std::string debugValuesProgramName(const DebugView& view);  // "debug.values.<name>": viewValue() as floats
// Adds the views' programs to the shader variant table (render/shader_variants.h), the two above
// per view, once however often it is called: the renderer calls it as it is made, and so does
// whatever asks the table for them without a renderer (the shader and table tests).
void registerDebugViewPrograms();

}  // namespace oasis
