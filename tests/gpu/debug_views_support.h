// What the debug-view tests share (debug_views_test.cpp, debug_view_semantics_test.cpp,
// frame_sink_test.cpp): every view's name, the overview's among them.
#pragma once
#include <string>
#include <vector>

#include "gpu_test.h"

#include "debug/debug_views.h"

namespace oasis::gputest {

inline std::vector<std::string> allViewNames() {
    std::vector<std::string> names;
    for (const DebugView& view : debugViews()) names.push_back(view.name);
    names.push_back(kOverviewName);
    return names;
}

}  // namespace oasis::gputest
