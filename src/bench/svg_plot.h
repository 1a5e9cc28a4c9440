// A small SVG scatter-plot writer for the bench: side-by-side panels, axes with ticks, points
// coloured by series with a legend, horizontal error bars for x's intervals, and marked frontiers (the panel's, and each series' own) whose
// points are labelled without overlap (crowded labels are stacked with a leader line, or left out).
#pragma once
#include <string>
#include <vector>

namespace oasis {

struct PlotPoint {
    double x = 0.0, y = 0.0;
    std::string series;  // picks the colour (first series seen gets the first colour)
    std::string label;   // drawn beside frontier points (always in the point's tooltip)
    bool frontier = false;        // on the panel's frontier: outlined, joined by the dashed grey line
    bool seriesFrontier = false;  // on its series' own frontier: joined by a thin line of its colour
    // x's 95% interval, drawn as an error bar (the bench's time); xLow > xHigh: none.
    double xLow = 0.0, xHigh = -1.0;
    bool hasInterval() const { return xLow <= xHigh; }
};

struct PlotPanel {
    std::string title;
    std::vector<PlotPoint> points;
};

struct PlotText {
    std::string title, xLabel, yLabel, footnote;
    int columns = 0;  // panels per row; 0: all in one row
};

// "Nice" tick values (steps of 1, 2 or 5 times a power of ten) covering [low, high], about `count`.
std::vector<double> niceTicks(double low, double high, int count = 5);

std::string scatterPlotSvg(const std::vector<PlotPanel>& panels, const PlotText& text);

}  // namespace oasis
