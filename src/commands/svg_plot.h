// A small SVG scatter-plot writer for the bench: side-by-side panels, axes with ticks, points
// coloured by series with a legend, and a marked frontier (a polyline through its points, labelled).
#pragma once
#include <string>
#include <vector>

namespace oasis {

struct PlotPoint {
    double x = 0.0, y = 0.0;
    std::string series;  // picks the colour (first series seen gets the first colour)
    std::string label;   // drawn beside frontier points
    bool frontier = false;
};

struct PlotPanel {
    std::string title;
    std::vector<PlotPoint> points;
};

struct PlotText {
    std::string title, xLabel, yLabel, footnote;
};

// "Nice" tick values (steps of 1, 2 or 5 times a power of ten) covering [low, high], about `count`.
std::vector<double> niceTicks(double low, double high, int count = 5);

std::string scatterPlotSvg(const std::vector<PlotPanel>& panels, const PlotText& text);

}  // namespace oasis
