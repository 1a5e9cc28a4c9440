// The legend strip under a single-view image (render, compare's difference.png): the view's name
// and what its colours mean, its scale with numbers (a colour bar with ticks for continuous views,
// swatches for categorical ones), the range in use, and the counts of NaN, infinite and negative
// values with their overlay swatches. Drawn with Dear ImGui's font on the current GL context.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "debug/debug_views.h"
#include "debug/label_overlay.h"
#include "debug/view_controls.h"
#include "render/image.h"

namespace oasis {

struct Legend {
    std::string title;                       // "normal: world normal xyz as rgb = 0.5 + 0.5 n"
    LegendScale scale = LegendScale::None;
    double low = 0.0, high = 1.0;            // the bar's numbers (DepthRamp near..far, SignedLog -D..D,
                                             // Grey the range, DifferenceHeat 0..full scale)
    std::vector<std::string> notes;          // further lines: the channel and range, the counts
    unsigned overlaySwatches = 0;            // OverlayBits whose checker swatches follow the notes
};

// The legend of a view of the last frame: its table text and scale; with the controls' values
// shown, the channel, the range in use and the grey bar; always the value counts.
// `waterNote` (debug_views.h waterNote) says what the view shows under the water.
Legend viewLegend(const DebugView& view, const ViewControls& controls, const ValueStatistics& statistics,
                  double nearPlane, double farPlane, double viewDistance, const std::string& waterNote = {});

// Narrower images get no legend: its text would wrap into a strip taller than the frame.
inline constexpr int kMinLegendWidth = 160;

class LegendRenderer {
public:
    // The strip, `width` pixels wide (its height follows from the font scale the width gives);
    // an empty image below kMinLegendWidth.
    Image draw(const Legend& legend, int width);

private:
    std::unique_ptr<LabelOverlay> overlay_;
};

// The colours the views draw, as the legend's bars sample them (twins of shaders/debug_view.frag's
// ramp() and heat()).
void depthRampColour(float t, uint8_t rgb[3]);
void lightHeatColour(float count, uint8_t rgb[3]);

}  // namespace oasis
