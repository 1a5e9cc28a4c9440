// Covers the point labels of src/bench/svg_plot.h: in a crowded panel (the bench's layouts sit
// on nearly the same point) no two labels overlap and every label stays inside the plot.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "bench/svg_plot.h"

namespace oasis {
namespace {

struct DrawnLabel {
    double x0, y0, x1, y1;
    std::string text;
};

// The labels' boxes as a renderer draws them at most: 10 px sans-serif is under 6 px a character,
// 8 px above the baseline and 3 below.
std::vector<DrawnLabel> pointLabels(const std::string& svg) {
    std::regex label("<text class=\"point-label\" x=\"([-0-9.]+)\" y=\"([-0-9.]+)\"( text-anchor=\"end\")? "
                     "font-size=\"10.0\" fill=\"[^\"]*\">([^<]*)</text>");
    std::vector<DrawnLabel> labels;
    for (std::sregex_iterator it(svg.begin(), svg.end(), label), end; it != end; ++it) {
        double x = std::stod((*it)[1]), y = std::stod((*it)[2]), width = 6.0 * double((*it)[4].length());
        double x0 = (*it)[3].matched ? x - width : x;
        labels.push_back({x0, y - 8, x0 + width, y + 3, (*it)[4]});
    }
    return labels;
}

// A bench-like panel: per knob setting four deferred layouts within a few ms and a forward point,
// every one on a frontier so that every one is labelled.
PlotPanel crowdedPanel() {
    PlotPanel panel{"640x360, 0 lights", {}};
    const char* layouts[] = {"full", "standard", "compact", "compact+reversed-z"};
    const char* variations[] = {"default", "reflections=off", "grid=coarse", "vegetation=0.5", "grid=fine"};
    for (int v = 0; v < 5; ++v) {
        double ms = 40.0 + 20.0 * v, error = 10.0 - 2.0 * v;
        for (int l = 0; l < 4; ++l)
            panel.points.push_back({ms + 0.4 * l, error + 0.01 * l, "deferred", std::string(layouts[l]) + " " + variations[v],
                                    l == 0, true});
        panel.points.push_back({ms - 3.0, error + 0.02, "forward", variations[v], true, true});
    }
    return panel;
}

TEST(SvgPlotLabels, NoTwoLabelsOverlapAndAllStayInThePlot) {
    PlotPanel panel = crowdedPanel();
    std::string svg = scatterPlotSvg({panel}, {"title", "ms", "RMSE", "note"});
    std::vector<DrawnLabel> labels = pointLabels(svg);
    EXPECT_EQ(labels.size(), panel.points.size()) << "a label was left out";
    // The panel's plot area: 70 px in from the left, 40 below the panel's top (itself 30 down).
    for (const DrawnLabel& a : labels) {
        EXPECT_GE(a.x0, 70.0) << a.text;
        EXPECT_LE(a.x1, 560.0 - 20.0) << a.text;
        EXPECT_GE(a.y0, 30.0 + 40.0) << a.text;
        EXPECT_LE(a.y1, 30.0 + 420.0 - 60.0) << a.text;
    }
    for (size_t i = 0; i < labels.size(); ++i)
        for (size_t j = i + 1; j < labels.size(); ++j) {
            const DrawnLabel &a = labels[i], &b = labels[j];
            EXPECT_FALSE(a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1)
                << "'" << a.text << "' overlaps '" << b.text << "'";
        }
    // The crowd cannot all sit beside their points: some are moved and joined by a leader line.
    EXPECT_NE(svg.find("<line class=\"leader\""), std::string::npos);
}

// More labels than the plot can hold: the ones that do not fit are left out (each point keeps its
// label as a tooltip) rather than drawn over others.
TEST(SvgPlotLabels, LabelsThatCannotFitAreLeftOutNotOverlapped) {
    PlotPanel panel{"crowd", {}};
    for (int i = 0; i < 200; ++i)
        panel.points.push_back({1.0 + 0.001 * i, 1.0, "deferred", "a rather long label number " + std::to_string(i), true, true});
    panel.points.push_back({2.0, 0.0, "forward", "far", true, true});
    std::string svg = scatterPlotSvg({panel}, {"title", "ms", "RMSE", "note"});
    std::vector<DrawnLabel> labels = pointLabels(svg);
    EXPECT_LT(labels.size(), panel.points.size());
    EXPECT_GT(labels.size(), 10u);
    for (size_t i = 0; i < labels.size(); ++i)
        for (size_t j = i + 1; j < labels.size(); ++j) {
            const DrawnLabel &a = labels[i], &b = labels[j];
            EXPECT_FALSE(a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1)
                << "'" << a.text << "' overlaps '" << b.text << "'";
        }
    EXPECT_NE(svg.find("<title>deferred a rather long label number 199</title>"), std::string::npos);
}

}  // namespace
}  // namespace oasis
