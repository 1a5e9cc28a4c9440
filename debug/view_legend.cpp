// Legend strips: text, colour bars with numbered ticks, swatches, drawn into a small target with
// the overview labels' private ImGui context and read back as an image.
#include "debug/view_legend.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gl/objects.h"

namespace oasis {
namespace {

constexpr float kGlyphWidth = 7.0f;   // Dear ImGui's built-in font (ProggyClean, monospace) at scale 1
constexpr float kLineHeight = 15.0f;

ImU32 colour(const uint8_t rgb[3]) { return IM_COL32(rgb[0], rgb[1], rgb[2], 255); }
ImU32 grey(float t) {
    auto v = uint8_t(std::lround(std::clamp(t, 0.0f, 1.0f) * 255.0f));
    return IM_COL32(v, v, v, 255);
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.4g", value);
    return text;
}

// The colour a continuous scale draws at t in 0..1, and the number it stands for there.
ImU32 barColour(const Legend& legend, float t) {
    uint8_t rgb[3];
    switch (legend.scale) {
        case LegendScale::DepthRamp:
        case LegendScale::LinearRamp: depthRampColour(t, rgb); return colour(rgb);
        case LegendScale::DifferenceHeat: differenceHeatColour(t, rgb); return colour(rgb);
        default: return grey(t);
    }
}

double barValue(const Legend& legend, double t) {
    switch (legend.scale) {
        case LegendScale::DepthRamp: return legend.low * std::pow(legend.high / legend.low, t);
        case LegendScale::SignedLog: {
            double u = 2.0 * t - 1.0;
            return (u < 0 ? -1.0 : 1.0) * (std::pow(1.0 + legend.high, std::fabs(u)) - 1.0);
        }
        default: return legend.low + t * (legend.high - legend.low);
    }
}

struct Swatch {
    uint8_t rgb[3];
    std::string text;
};

std::vector<Swatch> swatchesOf(LegendScale scale) {
    switch (scale) {
        case LegendScale::StencilSwatches:
            return {{{0, 0, 0}, "0 nothing (sky)"}, {{242, 158, 31}, "1 terrain"}, {{38, 115, 242}, "2 water"},
                    {{51, 217, 89}, "3 plants"}};
        case LegendScale::InfoFlags:
            return {{{0, 0, 204}, "blue 0.8 sky"}, {{0, 0, 128}, "0.5 reflected"}, {{0, 0, 64}, "0.25 plant"},
                    {{0, 0, 191}, "0.75 reflected plant"}};
        case LegendScale::LightHeat: {
            std::vector<Swatch> swatches{{{26, 26, 26}, "0"}};
            for (float count : {1.0f, 2.0f, 4.0f, 8.0f, 16.0f}) {
                Swatch swatch{{0, 0, 0}, count < 16.0f ? number(count) : "16+"};
                lightHeatColour(count, swatch.rgb);
                swatches.push_back(swatch);
            }
            return swatches;
        }
        default: return {};
    }
}

bool hasBar(LegendScale scale) {
    return scale == LegendScale::DepthRamp || scale == LegendScale::SignedLog || scale == LegendScale::Grey ||
           scale == LegendScale::DifferenceHeat || scale == LegendScale::LinearRamp;
}

struct OverlaySwatch {
    OverlayBits bit;
    const char* text;
};
constexpr OverlaySwatch kOverlaySwatches[] = {
    {kOverlayNan, "NaN"}, {kOverlayInfinity, "+Inf (-Inf: grey checks)"}, {kOverlayNegative, "negative"}};

}  // namespace

void depthRampColour(float t, uint8_t rgb[3]) {
    t = std::clamp(t, 0.0f, 1.0f);
    const float low[3] = {0.05f, 0.03f, 0.25f}, mid[3] = {0.10f, 0.60f, 0.55f}, high[3] = {0.99f, 0.91f, 0.15f};
    for (int c = 0; c < 3; ++c) {
        float v = t < 0.5f ? low[c] + (mid[c] - low[c]) * t * 2.0f : mid[c] + (high[c] - mid[c]) * (t * 2.0f - 1.0f);
        rgb[c] = uint8_t(std::lround(v * 255.0f));
    }
}

void lightHeatColour(float count, uint8_t rgb[3]) {
    const float stops[6][3] = {{0.0f, 0.0f, 0.0f}, {0.1f, 0.2f, 0.9f}, {0.1f, 0.8f, 0.3f},
                               {0.95f, 0.9f, 0.1f}, {0.95f, 0.15f, 0.05f}, {1.0f, 1.0f, 1.0f}};
    float t = std::clamp(std::log2(std::max(count, 1e-6f)) / 4.0f, 0.0f, 1.0f) * 4.0f + 1.0f;
    int i = std::min(int(std::floor(t)), 4);
    for (int c = 0; c < 3; ++c)
        rgb[c] = uint8_t(std::lround((stops[i][c] + (stops[i + 1][c] - stops[i][c]) * (t - float(i))) * 255.0f));
}

Legend viewLegend(const DebugView& view, const ViewControls& controls, const ValueStatistics& statistics,
                  double nearPlane, double farPlane, double viewDistance, const std::string& waterNote) {
    Legend legend;
    ViewChannel channel = controls.channel.value_or(defaultChannel(view));
    if (controls.showValues()) {
        auto [low, high] = rangeInUse(controls, statistics);
        legend.title = view.name + ": its values, channel " + describeChannel(view, channel) + ", black " +
                       number(low) + " to white " + number(high);
        legend.scale = LegendScale::Grey;
        legend.low = low;
        legend.high = high;
        legend.notes.push_back(std::string("range ") + (controls.range ? "given (--range)" : "fitted to the frame's finite values") +
                               "; values r, g, b, a: " + [&] {
                                   std::string names;
                                   for (const std::string& name : view.values) names += (names.empty() ? "" : ", ") + name;
                                   return names;
                               }());
    } else {
        legend.title = view.name + ": " + view.legend;
        legend.scale = view.scale;
        if (view.scale == LegendScale::DepthRamp) legend.low = nearPlane, legend.high = farPlane;
        if (view.scale == LegendScale::SignedLog) legend.low = -viewDistance, legend.high = viewDistance;
    }
    char counts[256];
    std::snprintf(counts, sizeof(counts),
                  "%s: %ld values, NaN %ld, +Inf %ld, -Inf %ld, negative %ld; finite min %s, max %s",
                  describeChannel(view, channel).c_str(), statistics.values, statistics.nan, statistics.positiveInfinity,
                  statistics.negativeInfinity, statistics.negative, number(statistics.min).c_str(),
                  number(statistics.max).c_str());
    legend.notes.push_back(counts);
    if (!waterNote.empty()) legend.notes.push_back(waterNote);
    legend.overlaySwatches = controls.overlay;
    return legend;
}

Image LegendRenderer::draw(const Legend& legend, int width) {
    if (width < kMinLegendWidth) return Image();
    const float scale = std::clamp(float(width) / 640.0f, 1.0f, 2.0f);
    const float pad = 4.0f * scale, line = kLineHeight * scale, textWidth = float(width) - 2.0f * pad;
    if (!overlay_) overlay_ = std::make_unique<LabelOverlay>();
    // The characters over the width are a lower bound; ImGui wraps at word ends and needs more
    // lines where words do not fill a line (at 320 wide difference.png's title took three where
    // two were reserved, and the colour bar hid "levels": issue 31, defect 6). Never fewer lines
    // than before, so legends that fitted stay as they were.
    auto linesOf = [&](const std::string& text) {
        int estimate = std::max(1, int(std::ceil(float(text.size()) * kGlyphWidth * scale / std::max(textWidth, 1.0f))));
        return std::max(estimate, overlay_->wrappedLines(text, textWidth, scale));
    };
    int textLines = linesOf(legend.title);
    for (const std::string& note : legend.notes) textLines += linesOf(note);
    bool bar = hasBar(legend.scale), swatches = !swatchesOf(legend.scale).empty(), overlay = legend.overlaySwatches != 0;
    int height = int(std::ceil(2.0f * pad + float(textLines) * line + (bar ? 2.0f * line + pad : 0.0f) +
                               (swatches ? line + pad : 0.0f) + (overlay ? line : 0.0f)));

    gl::Texture target = gl::createTargetTexture("view legend", GL_RGBA8, width, height);
    gl::Framebuffer framebuffer = gl::createFramebuffer("view legend");
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.name());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.name(), 0);
    glViewport(0, 0, width, height);
    glClearColor(0.09f, 0.09f, 0.09f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    overlay_->drawWith([&](ImDrawList& draw) {
        const ImU32 white = IM_COL32(235, 235, 235, 255);
        float y = pad;
        auto text = [&](const std::string& content) {
            draw.AddText(nullptr, 0.0f, ImVec2(pad, y), white, content.c_str(), nullptr, textWidth);
            y += float(linesOf(content)) * line;
        };
        text(legend.title);
        if (bar) {
            // The colour bar, then five numbered ticks under it.
            y += pad * 0.5f;
            const int segments = 64;
            float barWidth = textWidth, x0 = pad;
            for (int i = 0; i < segments; ++i) {
                float t0 = float(i) / segments, t1 = float(i + 1) / segments;
                draw.AddRectFilledMultiColor(ImVec2(x0 + t0 * barWidth, y), ImVec2(x0 + t1 * barWidth + 1.0f, y + line * 0.8f),
                                             barColour(legend, t0), barColour(legend, t1), barColour(legend, t1),
                                             barColour(legend, t0));
            }
            y += line * 0.8f;
            for (int tick = 0; tick <= 4; ++tick) {
                float t = float(tick) / 4.0f, x = x0 + t * barWidth;
                std::string label = number(barValue(legend, t));
                if (legend.scale == LegendScale::DifferenceHeat && tick == 4) label += "+";
                float labelWidth = float(label.size()) * kGlyphWidth * scale;
                float left = std::clamp(x - labelWidth * 0.5f, pad, float(width) - pad - labelWidth);
                draw.AddLine(ImVec2(x, y), ImVec2(x, y + line * 0.3f), white);
                draw.AddText(ImVec2(left, y + line * 0.25f), white, label.c_str());
            }
            y += line * 1.2f + pad;
        }
        if (swatches) {
            float x = pad;
            for (const Swatch& swatch : swatchesOf(legend.scale)) {
                draw.AddRectFilled(ImVec2(x, y), ImVec2(x + line * 0.8f, y + line * 0.8f), colour(swatch.rgb));
                draw.AddRect(ImVec2(x, y), ImVec2(x + line * 0.8f, y + line * 0.8f), IM_COL32(120, 120, 120, 255));
                draw.AddText(ImVec2(x + line, y), white, swatch.text.c_str());
                x += line + float(swatch.text.size() + 2) * kGlyphWidth * scale;
            }
            y += line + pad;
        }
        for (const std::string& note : legend.notes) text(note);
        if (overlay) {
            float x = pad;
            draw.AddText(ImVec2(x, y), white, "overlay:");
            x += 9.0f * kGlyphWidth * scale;
            for (const OverlaySwatch& entry : kOverlaySwatches) {
                if (!(legend.overlaySwatches & entry.bit)) continue;
                OverlayColours checker = overlayColours(entry.bit);
                float cell = line * 0.4f;
                for (int cy = 0; cy < 2; ++cy)
                    for (int cx = 0; cx < 2; ++cx)
                        draw.AddRectFilled(ImVec2(x + cx * cell, y + cy * cell), ImVec2(x + (cx + 1) * cell, y + (cy + 1) * cell),
                                           colour((cx + cy) % 2 == 0 ? checker.first : checker.second));
                draw.AddText(ImVec2(x + line, y), white, entry.text);
                x += line + float(std::string(entry.text).size() + 2) * kGlyphWidth * scale;
            }
        }
    }, width, height, scale);

    Image strip(width, height);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.name());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, strip.rgba.data());
    strip.flipRows();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return strip;
}

}  // namespace oasis
