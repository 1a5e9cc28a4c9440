// View controls: channel selection, range fitting, value statistics and the overlay, on the CPU
// over the values the GPU wrote, so the counts printed and the pixels painted come from one loop.
#include "debug/view_controls.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "debug/debug_views.h"

namespace oasis {
namespace {

struct ChannelName {
    ViewChannel channel;
    const char* name;
};
constexpr ChannelName kChannels[] = {{ViewChannel::Rgb, "rgb"}, {ViewChannel::R, "r"}, {ViewChannel::G, "g"},
                                     {ViewChannel::B, "b"},     {ViewChannel::A, "a"}, {ViewChannel::Luminance, "luminance"}};

// The value(s) of one pixel for a channel: up to three (rgb), Rec. 709 luminance for luminance.
int channelValues(const float* texel, ViewChannel channel, float out[3]) {
    switch (channel) {
        case ViewChannel::Rgb: out[0] = texel[0]; out[1] = texel[1]; out[2] = texel[2]; return 3;
        case ViewChannel::R: out[0] = texel[0]; return 1;
        case ViewChannel::G: out[0] = texel[1]; return 1;
        case ViewChannel::B: out[0] = texel[2]; return 1;
        case ViewChannel::A: out[0] = texel[3]; return 1;
        case ViewChannel::Luminance: out[0] = 0.2126f * texel[0] + 0.7152f * texel[1] + 0.0722f * texel[2]; return 1;
    }
    return 0;
}

}  // namespace

bool parseViewChannel(const std::string& text, ViewChannel& channel) {
    for (const ChannelName& entry : kChannels)
        if (text == entry.name) { channel = entry.channel; return true; }
    return false;
}

const char* viewChannelName(ViewChannel channel) {
    for (const ChannelName& entry : kChannels)
        if (entry.channel == channel) return entry.name;
    return "?";
}

std::string viewChannelNames() {
    std::string names;
    for (const ChannelName& entry : kChannels) names += std::string(names.empty() ? "" : ", ") + entry.name;
    return names;
}

bool viewHasChannel(const DebugView& view, ViewChannel channel) {
    size_t filled = view.values.size();
    switch (channel) {
        case ViewChannel::Rgb:
        case ViewChannel::Luminance: return filled >= 3;
        case ViewChannel::R: return filled >= 1;
        case ViewChannel::G: return filled >= 2;
        case ViewChannel::B: return filled >= 3;
        case ViewChannel::A: return filled >= 4;
    }
    return false;
}

ViewChannel defaultChannel(const DebugView& view) { return view.values.size() >= 3 ? ViewChannel::Rgb : ViewChannel::R; }

std::string describeChannel(const DebugView& view, ViewChannel channel) {
    auto named = [&](size_t index) { return index < view.values.size() ? view.values[index] : std::string("?"); };
    std::string name = viewChannelName(channel);
    switch (channel) {
        case ViewChannel::Rgb: return name + " (" + named(0) + ", " + named(1) + ", " + named(2) + ")";
        case ViewChannel::R: return name + " (" + named(0) + ")";
        case ViewChannel::G: return name + " (" + named(1) + ")";
        case ViewChannel::B: return name + " (" + named(2) + ")";
        case ViewChannel::A: return name + " (" + named(3) + ")";
        case ViewChannel::Luminance: return name + " (Rec. 709 of " + named(0) + ", " + named(1) + ", " + named(2) + ")";
    }
    return name;
}

bool parseOverlay(const std::string& text, unsigned& bits) {
    bits = 0;
    if (text == "none") return true;
    size_t start = 0;
    while (start <= text.size()) {
        size_t comma = text.find(',', start);
        std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (item == "nan") bits |= kOverlayNan;
        else if (item == "inf") bits |= kOverlayInfinity;
        else if (item == "negative") bits |= kOverlayNegative;
        else return false;
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return bits != 0;
}

std::string overlayNames(unsigned bits) {
    std::string names;
    if (bits & kOverlayNan) names += "nan";
    if (bits & kOverlayInfinity) names += std::string(names.empty() ? "" : ",") + "inf";
    if (bits & kOverlayNegative) names += std::string(names.empty() ? "" : ",") + "negative";
    return names.empty() ? "none" : names;
}

namespace {
bool undrawn(const DrawnPixels* drawn, size_t pixel) { return drawn && !drawn->empty() && !(*drawn)[pixel]; }
}  // namespace

ValueStatistics valueStatistics(const std::vector<float>& rgba, ViewChannel channel, const DrawnPixels* drawn) {
    ValueStatistics s;
    s.min = std::numeric_limits<double>::infinity();
    s.max = -std::numeric_limits<double>::infinity();
    float values[3];
    for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
        if (undrawn(drawn, i / 4)) { ++s.undrawn; continue; }
        int count = channelValues(&rgba[i], channel, values);
        for (int c = 0; c < count; ++c) {
            float v = values[c];
            ++s.values;
            if (std::isnan(v)) { ++s.nan; continue; }
            if (std::isinf(v)) { ++(v > 0 ? s.positiveInfinity : s.negativeInfinity); continue; }
            if (v < 0.0f) ++s.negative;
            s.min = std::min(s.min, double(v));
            s.max = std::max(s.max, double(v));
            s.anyFinite = true;
        }
    }
    if (!s.anyFinite) s.min = s.max = 0.0;
    return s;
}

std::pair<double, double> rangeInUse(const ViewControls& controls, const ValueStatistics& statistics) {
    if (controls.range) return *controls.range;
    if (statistics.max > statistics.min) return {statistics.min, statistics.max};
    return {statistics.min, statistics.min + 1.0};
}

OverlayColours overlayColours(OverlayBits kind) {
    switch (kind) {
        case kOverlayNan: return {{255, 0, 255}, {0, 0, 0}};
        case kOverlayInfinity: return {{255, 0, 255}, {255, 255, 255}};
        case kOverlayNegative: return {{255, 0, 255}, {0, 255, 255}};
    }
    return {{255, 0, 255}, {0, 0, 0}};
}

Image mapViewValues(const std::vector<float>& rgba, int width, int height, ViewChannel channel,
                    std::pair<double, double> range, unsigned overlay, const DrawnPixels* drawn) {
    Image image(width, height);
    const double low = range.first, scale = 1.0 / (range.second - range.first);
    float values[3];
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            int count = channelValues(&rgba[(size_t(y) * size_t(width) + size_t(x)) * 4], channel, values);
            uint8_t* out = image.pixel(x, height - 1 - y);
            bool shown = !undrawn(drawn, size_t(y) * size_t(width) + size_t(x));
            for (int c = 0; c < 3; ++c) {
                if (!shown) { out[c] = 0; continue; }  // black = not drawn, as the depth view's cleared
                double v = values[count == 3 ? c : 0];
                double t = std::isfinite(v) ? std::clamp((v - low) * scale, 0.0, 1.0) : (v > 0 ? 1.0 : 0.0);
                out[c] = uint8_t(std::lround(t * 255.0));
            }
            out[3] = 255;
        }
    paintOverlay(image, rgba, channel, overlay, drawn);
    return image;
}

void paintOverlay(Image& image, const std::vector<float>& rgba, ViewChannel channel, unsigned overlay,
                  const DrawnPixels* drawn) {
    paintOverlayIn(image, {0, 0, image.width, image.height}, rgba, image.width, image.height, channel, overlay, drawn);
}

void paintOverlayIn(Image& image, ImageRect rect, const std::vector<float>& rgba, int frameWidth, int frameHeight,
                    ViewChannel channel, unsigned overlay, const DrawnPixels* drawn) {
    const OverlayColours nan = overlayColours(kOverlayNan), inf = overlayColours(kOverlayInfinity),
                         negative = overlayColours(kOverlayNegative), negativeInfinity{{255, 0, 255}, {128, 128, 128}};
    float values[3];
    for (int ty = 0; ty < rect.height; ++ty)
        for (int tx = 0; tx < rect.width; ++tx) {
            // The frame's texel under the rectangle's pixel centre; y counts from the bottom in GL.
            int x = int((tx + 0.5) * frameWidth / rect.width), y = int((ty + 0.5) * frameHeight / rect.height);
            if (undrawn(drawn, size_t(y) * size_t(frameWidth) + size_t(x))) continue;
            int count = channelValues(&rgba[(size_t(y) * size_t(frameWidth) + size_t(x)) * 4], channel, values);
            const OverlayColours* paint = nullptr;
            for (int c = 0; c < count && !paint; ++c)
                if ((overlay & kOverlayNan) && std::isnan(values[c])) paint = &nan;
            for (int c = 0; c < count && !paint; ++c)
                if ((overlay & kOverlayInfinity) && std::isinf(values[c])) paint = values[c] > 0 ? &inf : &negativeInfinity;
            for (int c = 0; c < count && !paint; ++c)
                if ((overlay & kOverlayNegative) && values[c] < 0.0f) paint = &negative;
            if (!paint) continue;
            const uint8_t* colour = ((tx / 2 + ty / 2) % 2 == 0) ? paint->first : paint->second;
            uint8_t* out = image.pixel(rect.x + tx, rect.y + rect.height - 1 - ty);
            out[0] = colour[0], out[1] = colour[1], out[2] = colour[2], out[3] = 255;
        }
}

}  // namespace oasis
