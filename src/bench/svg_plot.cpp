// SVG scatter plots written by hand: one <svg> with a <g> per panel.
#include "bench/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

namespace oasis {
namespace {

constexpr double kPanelWidth = 560, kPanelHeight = 420;
constexpr double kLeft = 70, kRight = 20, kTop = 40, kBottom = 60;  // margins inside a panel
const char* kColours[] = {"#d95f02", "#1b9e77", "#7570b3", "#e7298a", "#66a61e", "#e6ab02"};

std::string escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '&') out += "&amp;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.1f", value);
    return text;
}

std::string tickLabel(double value, double step) {
    char text[32];
    int decimals = step >= 1.0 ? 0 : int(std::ceil(-std::log10(step) - 1e-9));
    std::snprintf(text, sizeof(text), "%.*f", decimals, value);
    return text;
}

struct Range {
    double low, high;
};

Range paddedRange(double low, double high) {
    if (!(high > low)) {  // one value (or none): open a window around it
        double pad = std::max(std::fabs(low) * 0.1, 1.0);
        return {low - pad, high + pad};
    }
    double pad = (high - low) * 0.08;
    return {low - pad, high + pad};
}

// Point labels: 10 px sans-serif, at most ~0.6 em a character (DejaVu Sans, rsvg's default, is
// the widest common one), so a box of that size bounds what a renderer draws.
constexpr double kLabelFontSize = 10, kLabelCharWidth = 6.0, kLabelAscent = 8, kLabelDescent = 3;
constexpr double kLabelGap = 8, kLabelRow = 12;  // beside the point; one row of a stack
constexpr int kLabelRows = 8;                    // how far up or down a label may move from its point

struct Box {
    double x0, y0, x1, y1;
    bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
    bool inside(const Box& o) const { return x0 >= o.x0 && x1 <= o.x1 && y0 >= o.y0 && y1 <= o.y1; }
};

struct PlacedLabel {
    double x = 0, y = 0;  // the text's anchor and baseline
    bool rightAligned = false;
    bool leader = false;  // moved off its point: a thin line joins them
};

Box labelBox(const PlacedLabel& label, size_t characters) {
    double width = kLabelCharWidth * double(characters);
    double x0 = label.rightAligned ? label.x - width : label.x;
    return {x0, label.y - kLabelAscent, x0 + width, label.y + kLabelDescent};
}

// Places each label beside its point where it overlaps no label placed before it and stays in the
// plot; crowded points get theirs stacked above or below with a leader line. Earlier labels win:
// first a spot that covers no point either, then one that covers only points. A label with no
// spot is left out (its point keeps the label as a tooltip). Returns a spot per label, or none.
std::vector<std::optional<PlacedLabel>> placeLabels(const std::vector<std::pair<double, double>>& anchors,
                                                    const std::vector<std::string>& texts,
                                                    const std::vector<std::pair<double, double>>& points,
                                                    const Box& plot) {
    std::vector<Box> taken;
    std::vector<std::optional<PlacedLabel>> placed(anchors.size());
    auto coversAPoint = [&](const Box& box, size_t own) {
        for (const auto& [x, y] : points) {
            if (x == anchors[own].first && y == anchors[own].second) continue;
            if (box.overlaps({x - 4, y - 4, x + 4, y + 4})) return true;
        }
        return false;
    };
    for (size_t i = 0; i < anchors.size(); ++i) {
        auto [px, py] = anchors[i];
        for (int pass = 0; pass < 2 && !placed[i]; ++pass)
            for (int row = 0; row <= kLabelRows && !placed[i]; ++row)
                for (double baseline : {py - 6 - kLabelRow * row, py + 14 + kLabelRow * row})
                    for (bool rightAligned : {false, true}) {
                        double x = rightAligned ? px - kLabelGap : px + kLabelGap;
                        PlacedLabel label{x, baseline, rightAligned, row > 0};
                        Box box = labelBox(label, texts[i].size());
                        if (placed[i] || !box.inside(plot) || (pass == 0 && coversAPoint(box, i))) continue;
                        if (std::any_of(taken.begin(), taken.end(), [&](const Box& t) { return t.overlaps(box); }))
                            continue;
                        placed[i] = label;
                        taken.push_back(box);
                    }
    }
    return placed;
}

}  // namespace

std::vector<double> niceTicks(double low, double high, int count) {
    std::vector<double> ticks;
    if (!(high > low) || count < 1 || !std::isfinite(low) || !std::isfinite(high)) return ticks;
    double raw = (high - low) / count;
    double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (double factor : {1.0, 2.0, 5.0, 10.0})
        if (raw <= factor * magnitude * (1.0 + 1e-9)) { step = factor * magnitude; break; }
    for (double t = std::ceil(low / step - 1e-9) * step; t <= high + step * 1e-9; t += step)
        ticks.push_back(std::fabs(t) < step * 1e-9 ? 0.0 : t);
    return ticks;
}

std::string scatterPlotSvg(const std::vector<PlotPanel>& panels, const PlotText& text) {
    std::map<std::string, std::string> colourOf;
    std::vector<std::string> seriesOrder;
    for (const PlotPanel& panel : panels)
        for (const PlotPoint& point : panel.points)
            if (!colourOf.count(point.series)) {
                colourOf[point.series] = kColours[seriesOrder.size() % (sizeof(kColours) / sizeof(kColours[0]))];
                seriesOrder.push_back(point.series);
            }
    size_t columns = text.columns > 0 ? size_t(text.columns) : std::max<size_t>(1, panels.size());
    size_t rows = std::max<size_t>(1, (panels.size() + columns - 1) / columns);
    double width = kPanelWidth * double(std::min(columns, std::max<size_t>(1, panels.size())));
    double height = kPanelHeight * double(rows) + 70;
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(width) + "\" height=\"" +
                      number(height) + "\" viewBox=\"0 0 " + number(width) + " " + number(height) +
                      "\" font-family=\"sans-serif\" font-size=\"12\">\n";
    svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg += "<text x=\"" + number(width / 2) + "\" y=\"22\" text-anchor=\"middle\" font-size=\"16\">" +
           escape(text.title) + "</text>\n";
    for (size_t p = 0; p < panels.size(); ++p) {
        const PlotPanel& panel = panels[p];
        double ox = kPanelWidth * double(p % columns), oy = 30 + kPanelHeight * double(p / columns);
        double plotW = kPanelWidth - kLeft - kRight, plotH = kPanelHeight - kTop - kBottom;
        double xMin = 0, xMax = 0, yMin = 0, yMax = 0;
        for (size_t i = 0; i < panel.points.size(); ++i) {
            const PlotPoint& q = panel.points[i];
            double low = q.hasInterval() ? std::min(q.x, q.xLow) : q.x, high = q.hasInterval() ? std::max(q.x, q.xHigh) : q.x;
            xMin = i ? std::min(xMin, low) : low; xMax = i ? std::max(xMax, high) : high;
            yMin = i ? std::min(yMin, q.y) : q.y; yMax = i ? std::max(yMax, q.y) : q.y;
        }
        Range xr = paddedRange(xMin, xMax), yr = paddedRange(yMin, yMax);
        auto sx = [&](double x) { return ox + kLeft + (x - xr.low) / (xr.high - xr.low) * plotW; };
        auto sy = [&](double y) { return oy + kTop + plotH - (y - yr.low) / (yr.high - yr.low) * plotH; };
        svg += "<g>\n<text x=\"" + number(ox + kLeft + plotW / 2) + "\" y=\"" + number(oy + kTop - 10) +
               "\" text-anchor=\"middle\" font-size=\"14\">" + escape(panel.title) + "</text>\n";
        svg += "<rect x=\"" + number(ox + kLeft) + "\" y=\"" + number(oy + kTop) + "\" width=\"" + number(plotW) +
               "\" height=\"" + number(plotH) + "\" fill=\"none\" stroke=\"#333\"/>\n";
        std::vector<double> xTicks = niceTicks(xr.low, xr.high, 6), yTicks = niceTicks(yr.low, yr.high, 6);
        double xStep = xTicks.size() > 1 ? xTicks[1] - xTicks[0] : 1.0, yStep = yTicks.size() > 1 ? yTicks[1] - yTicks[0] : 1.0;
        for (double t : xTicks) {
            double x = sx(t), y = oy + kTop + plotH;
            svg += "<line x1=\"" + number(x) + "\" y1=\"" + number(y) + "\" x2=\"" + number(x) + "\" y2=\"" +
                   number(y + 5) + "\" stroke=\"#333\"/><line x1=\"" + number(x) + "\" y1=\"" + number(oy + kTop) +
                   "\" x2=\"" + number(x) + "\" y2=\"" + number(y) + "\" stroke=\"#eee\"/><text x=\"" + number(x) +
                   "\" y=\"" + number(y + 18) + "\" text-anchor=\"middle\">" + tickLabel(t, xStep) + "</text>\n";
        }
        for (double t : yTicks) {
            double x = ox + kLeft, y = sy(t);
            svg += "<line x1=\"" + number(x - 5) + "\" y1=\"" + number(y) + "\" x2=\"" + number(x) + "\" y2=\"" +
                   number(y) + "\" stroke=\"#333\"/><line x1=\"" + number(x) + "\" y1=\"" + number(y) + "\" x2=\"" +
                   number(x + plotW) + "\" y2=\"" + number(y) + "\" stroke=\"#eee\"/><text x=\"" + number(x - 8) +
                   "\" y=\"" + number(y + 4) + "\" text-anchor=\"end\">" + tickLabel(t, yStep) + "</text>\n";
        }
        svg += "<text x=\"" + number(ox + kLeft + plotW / 2) + "\" y=\"" + number(oy + kTop + plotH + 40) +
               "\" text-anchor=\"middle\">" + escape(text.xLabel) + "</text>\n";
        double yLabelX = ox + 18, yLabelY = oy + kTop + plotH / 2;
        svg += "<text x=\"" + number(yLabelX) + "\" y=\"" + number(yLabelY) + "\" text-anchor=\"middle\" transform=\"rotate(-90 " +
               number(yLabelX) + " " + number(yLabelY) + ")\">" + escape(text.yLabel) + "</text>\n";
        // Each series' own frontier: a thin line of its colour; its points are labelled too.
        std::vector<const PlotPoint*> labelled;
        for (const std::string& series : seriesOrder) {
            std::vector<const PlotPoint*> own;
            for (const PlotPoint& q : panel.points)
                if (q.seriesFrontier && q.series == series) own.push_back(&q);
            std::sort(own.begin(), own.end(), [](const PlotPoint* a, const PlotPoint* b) {
                return a->x != b->x ? a->x < b->x : a->y > b->y;
            });
            if (own.size() < 2) continue;
            svg += "<polyline class=\"pareto-series\" fill=\"none\" stroke=\"" + colourOf[series] +
                   "\" stroke-width=\"1\" stroke-dasharray=\"2 2\" points=\"";
            for (const PlotPoint* q : own) {
                svg += number(sx(q->x)) + "," + number(sy(q->y)) + " ";
                if (!q->frontier) labelled.push_back(q);
            }
            svg += "\"/>\n";
        }
        // The frontier: a polyline through its points in order of x.
        std::vector<const PlotPoint*> frontier;
        for (const PlotPoint& q : panel.points)
            if (q.frontier) frontier.push_back(&q);
        std::sort(frontier.begin(), frontier.end(), [](const PlotPoint* a, const PlotPoint* b) {
            return a->x != b->x ? a->x < b->x : a->y > b->y;
        });
        if (!frontier.empty()) {
            svg += "<polyline class=\"pareto\" fill=\"none\" stroke=\"#444\" stroke-width=\"1.5\" stroke-dasharray=\"5 3\" points=\"";
            for (const PlotPoint* q : frontier) svg += number(sx(q->x)) + "," + number(sy(q->y)) + " ";
            svg += "\"/>\n";
        }
        // The time's 95% interval under each point: a bar with end ticks in the point's colour.
        for (const PlotPoint& q : panel.points) {
            if (!q.hasInterval()) continue;
            double x0 = sx(q.xLow), x1 = sx(q.xHigh), y = sy(q.y);
            svg += "<path class=\"error-bar\" stroke=\"" + colourOf[q.series] + "\" stroke-width=\"1\" fill=\"none\" d=\"M" +
                   number(x0) + "," + number(y - 3) + "v6M" + number(x0) + "," + number(y) + "H" + number(x1) + "M" +
                   number(x1) + "," + number(y - 3) + "v6\"/>\n";
        }
        for (const PlotPoint& q : panel.points) {
            const std::string& colour = colourOf[q.series];
            svg += "<circle cx=\"" + number(sx(q.x)) + "\" cy=\"" + number(sy(q.y)) + "\" r=\"" +
                   (q.frontier ? "5.5" : "4") + "\" fill=\"" + colour + "\" fill-opacity=\"" +
                   (q.frontier ? "1" : "0.55") + "\"" + (q.frontier ? " stroke=\"black\" stroke-width=\"1.5\"" : "") +
                   "><title>" + escape(q.series + " " + q.label) + "</title></circle>\n";
        }
        // The panel's frontier first: its labels get the best spots.
        labelled.insert(labelled.begin(), frontier.begin(), frontier.end());
        std::vector<std::pair<double, double>> anchors, points;
        std::vector<std::string> texts;
        for (const PlotPoint* q : labelled) {
            anchors.push_back({sx(q->x), sy(q->y)});
            texts.push_back(q->label);
        }
        for (const PlotPoint& q : panel.points) points.push_back({sx(q.x), sy(q.y)});
        std::vector<std::optional<PlacedLabel>> spots =
            placeLabels(anchors, texts, points, {ox + kLeft, oy + kTop, ox + kLeft + plotW, oy + kTop + plotH});
        for (size_t i = 0; i < labelled.size(); ++i) {
            if (!spots[i]) continue;
            const PlacedLabel& spot = *spots[i];
            const std::string& colour = labelled[i]->frontier ? "#222" : colourOf[labelled[i]->series];
            if (spot.leader)
                svg += "<line class=\"leader\" x1=\"" + number(anchors[i].first) + "\" y1=\"" +
                       number(anchors[i].second) + "\" x2=\"" + number(spot.x) + "\" y2=\"" + number(spot.y - 3) + "\" stroke=\"" + colour +
                       "\" stroke-width=\"0.5\" stroke-opacity=\"0.7\"/>\n";
            svg += "<text class=\"point-label\" x=\"" + number(spot.x) + "\" y=\"" + number(spot.y) + "\"" +
                   (spot.rightAligned ? " text-anchor=\"end\"" : "") + " font-size=\"" + number(kLabelFontSize) +
                   "\" fill=\"" + colour + "\">" + escape(labelled[i]->label) + "</text>\n";
        }
        svg += "</g>\n";
    }
    // Legend: one swatch per series, and the frontier's mark.
    double lx = 20, ly = kPanelHeight * double(rows) + 45;
    for (const std::string& series : seriesOrder) {
        svg += "<circle cx=\"" + number(lx) + "\" cy=\"" + number(ly) + "\" r=\"5\" fill=\"" + colourOf[series] +
               "\"/><text x=\"" + number(lx + 10) + "\" y=\"" + number(ly + 4) + "\">" + escape(series) + "</text>\n";
        lx += 30 + 7.0 * double(series.size());
    }
    svg += "<line x1=\"" + number(lx) + "\" y1=\"" + number(ly) + "\" x2=\"" + number(lx + 30) + "\" y2=\"" + number(ly) +
           "\" stroke=\"#444\" stroke-width=\"1.5\" stroke-dasharray=\"5 3\"/><text x=\"" + number(lx + 36) + "\" y=\"" +
           number(ly + 4) + "\">Pareto frontier (outlined points)</text>\n";
    lx += 250;
    svg += "<line x1=\"" + number(lx) + "\" y1=\"" + number(ly) + "\" x2=\"" + number(lx + 30) + "\" y2=\"" + number(ly) +
           "\" stroke=\"#888\" stroke-width=\"1\" stroke-dasharray=\"2 2\"/><text x=\"" + number(lx + 36) + "\" y=\"" +
           number(ly + 4) + "\">frontier within one series (its colour)</text>\n";
    if (!text.footnote.empty())
        svg += "<text x=\"20\" y=\"" + number(ly + 20) + "\" font-size=\"10\" fill=\"#555\">" + escape(text.footnote) +
               "</text>\n";
    return svg + "</svg>\n";
}

}  // namespace oasis
