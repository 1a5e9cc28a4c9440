// The view controls, GL-free: which channel of a view's values to show (rgb, r, g, b, a,
// luminance), the range mapped to black..white (fitted to the frame's finite values, or given),
// and the overlay that paints NaN, infinities and (on request) negative values in checker
// patterns no view draws. The values come from the view's VIEW_VALUES pass (FrameViews::readValues).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/image.h"

namespace oasis {

struct DebugView;

enum class ViewChannel { Rgb, R, G, B, A, Luminance };
bool parseViewChannel(const std::string& text, ViewChannel& channel);
const char* viewChannelName(ViewChannel channel);
std::string viewChannelNames();  // "rgb, r, g, b, a, luminance"
// Whether the view has that channel: r..a need the view to fill it, rgb and luminance three.
bool viewHasChannel(const DebugView& view, ViewChannel channel);

enum OverlayBits : unsigned { kOverlayNan = 1, kOverlayInfinity = 2, kOverlayNegative = 4 };
bool parseOverlay(const std::string& text, unsigned& bits);  // "nan,inf,negative" or "none"
std::string overlayNames(unsigned bits);

struct ViewControls {
    std::optional<ViewChannel> channel;                // set: show the values, not the view's colours
    std::optional<std::pair<double, double>> range;    // set: this range; else fitted to the frame
    unsigned overlay = kOverlayNan | kOverlayInfinity;
    bool showValues() const { return channel.has_value() || range.has_value(); }
};

// Which pixels of the frame hold a drawn surface (1) and which nothing was drawn at (0, the sky),
// for views whose values mean nothing there (frame/view_mask.h); null or empty: every pixel.
using DrawnPixels = std::vector<uint8_t>;

// Over the chosen channel(s) of every drawn pixel (rgb: three values a pixel).
struct ValueStatistics {
    long values = 0, nan = 0, positiveInfinity = 0, negativeInfinity = 0, negative = 0;
    long undrawn = 0;  // pixels left out: nothing was drawn there
    double min = 0.0, max = 0.0;  // of the finite values (0 and 0 when there are none)
    bool anyFinite = false;
};
ValueStatistics valueStatistics(const std::vector<float>& rgba, ViewChannel channel, const DrawnPixels* drawn = nullptr);

// The range actually drawn: the given one, or the statistics' finite min..max (widened to a
// unit span when flat, so a constant frame maps to black rather than dividing by zero).
std::pair<double, double> rangeInUse(const ViewControls& controls, const ValueStatistics& statistics);

// The values (RGBA floats, bottom row first, as GL reads them) as an image (top row first): the
// channel mapped linearly from the range to black..white (rgb: each channel), clamped; overlaid
// pixels in 2x2 checkers of magenta with black (NaN), white (+Inf), grey (-Inf) or cyan (negative);
// pixels where nothing was drawn black, never overlaid.
Image mapViewValues(const std::vector<float>& rgba, int width, int height, ViewChannel channel,
                    std::pair<double, double> range, unsigned overlay, const DrawnPixels* drawn = nullptr);

// Paints the overlay's checkers over any image of the frame (a view's own colours too).
void paintOverlay(Image& image, const std::vector<float>& rgba, ViewChannel channel, unsigned overlay,
                  const DrawnPixels* drawn = nullptr);
// The same over one rectangle of `image` (x, y from the top) that shows the frame's values
// (frameWidth x frameHeight) scaled to it, as the overview's tiles sample them (nearest texel).
struct ImageRect { int x = 0, y = 0, width = 0, height = 0; };
void paintOverlayIn(Image& image, ImageRect rect, const std::vector<float>& rgba, int frameWidth, int frameHeight,
                    ViewChannel channel, unsigned overlay, const DrawnPixels* drawn = nullptr);
// The channel a view's statistics and legend use when none is asked for: rgb where the view has
// three values, else its first.
ViewChannel defaultChannel(const DebugView& view);
// "a (distance)", "rgb (x, y, z)", "luminance" for legends and reports.
std::string describeChannel(const DebugView& view, ViewChannel channel);

// The overlay's checker colours, for the legend's swatches.
struct OverlayColours { uint8_t first[3], second[3]; };
OverlayColours overlayColours(OverlayBits kind);

}  // namespace oasis
