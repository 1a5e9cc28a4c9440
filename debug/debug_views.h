// The debug views: one table (name, the target it shows, the shader remapping, what a person
// sees). The CLI's --view, the window's keys and menu, the overview grid and the tests all
// read this table, so a new view is one entry here (plus its VIEW_* remapping if it needs a new one).
#pragma once
#include <string>
#include <vector>

#include "render/gbuffer_layout.h"

namespace oasis {

enum class ViewSource { Final, Albedo, Normal, Position, Info, Depth, Stencil, Radiance, Reflection, PlantAtlas, Vegetation };

struct DebugView {
    std::string name;
    ViewSource source;
    std::string remapDefine;  // the VIEW_* define of shaders/debug_view.frag
    std::string legend;       // what the colours mean
};

const std::vector<DebugView>& debugViews();
const DebugView* findDebugView(const std::string& name);
std::string debugViewNames();  // "final, albedo, ..., overview" for help and errors
inline const char* kOverviewName = "overview";

// True when the view reads a G-buffer colour target (which only the deferred pipeline fills).
bool readsGBuffer(const DebugView& view);
std::string debugProgramName(const DebugView& view);  // "debug.<name>"

}  // namespace oasis
