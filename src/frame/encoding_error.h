// What a G-buffer layout's encoding costs in accuracy, per pixel: the same frame drawn deferred
// with the layout and with `full` (float targets, the reference), and where both hold the same
// surface, the angle between their normals (degrees) and the distance between their positions
// (world units, and in depth steps of the frame's depth convention). Both sides are decoded on the
// GPU, as the lighting pass reads them (the normal and position views' values).
#pragma once
#include <string>
#include <vector>

#include "render/frame_setup.h"
#include "render/gbuffer_layout.h"

namespace oasis {

class Renderer;

struct EncodingError {
    int width = 0, height = 0;
    std::string layout;
    // Per pixel, bottom row first; NaN where the two frames hold no common surface (sky, or the
    // flags differ), which the statistics skip.
    std::vector<float> normalDegrees, positionUnits, positionSteps;
    long surfaces = 0;  // pixels compared
};

// Renders `scene` deferred in `layout` and in `full` on `renderer` (left configured for `layout`
// again, its last frame the layout's) and compares them. Throws std::invalid_argument for `full`.
EncodingError measureEncodingError(Renderer& renderer, const SceneSettings& scene, const GBufferLayout& layout);

// Median, 99th percentile and maximum of the finite values.
struct ErrorSummary {
    double median = 0.0, p99 = 0.0, max = 0.0;
    long count = 0;
};
ErrorSummary summarizeError(const std::vector<float>& values);

// The encoding-error views: their names, what they show and which numbers.
struct EncodingErrorView {
    std::string name;
    std::string legend;
    const std::vector<float> EncodingError::*values;
};
const std::vector<EncodingErrorView>& encodingErrorViews();
const EncodingErrorView* findEncodingErrorView(const std::string& name);
std::string encodingErrorViewNames();  // "normal-error, position-error, position-error-steps"

}  // namespace oasis
