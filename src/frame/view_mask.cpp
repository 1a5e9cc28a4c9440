// The drawn-pixel mask of the debug views (frame/view_mask.h), from the Info view's flags,
// read back like any view's values.
#include "frame/view_mask.h"

#include "common/shared_constants.glsl"
#include "frame/renderer.h"

namespace oasis {

bool masksUndrawn(const DebugView& view) {
    // Depth too: its cleared far plane is the sky's "nothing drawn", as the probe says ("cleared").
    return view.source == ViewSource::Albedo || view.source == ViewSource::Normal ||
           view.source == ViewSource::Position || view.source == ViewSource::Depth;
}

DrawnPixels drawnPixels(Renderer& renderer, const DebugView& view) {
    if (!masksUndrawn(view)) return {};
    // The info view's values: specular power, intensity, the flag bits (exact as a float).
    const std::vector<float> info = renderer.views().readValues("info");
    DrawnPixels drawn(info.size() / 4);
    for (size_t i = 0; i < drawn.size(); ++i) drawn[i] = (unsigned(info[i * 4 + 2]) & OASIS_SURFACE_SKY) == 0u;
    return drawn;
}

std::string undrawnNote(const DebugView& view, long undrawn, bool valuesShown) {
    // Only where the values are drawn: the view's own colours show the sky as they always did.
    if (!masksUndrawn(view) || undrawn == 0 || !valuesShown) return {};
    return "black = not drawn (sky, " + std::to_string(undrawn) + " px): left out of the counts, range and overlay";
}

}  // namespace oasis
