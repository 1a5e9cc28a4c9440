// The overview's view controls: each tile's overlay and counts.
#include "frame/overview_overlay.h"

#include <algorithm>
#include <cstdio>

#include "frame/view_mask.h"
#include "debug/view_controls.h"

namespace oasis {

std::vector<std::string> overlayOverviewTiles(Image& image, Renderer& renderer, unsigned overlay) {
    std::vector<std::string> counts;
    const int width = renderer.targets().width(), height = renderer.targets().height();
    for (const OverviewTile& tile : overviewTiles(width, height)) {
        std::vector<float> values = renderer.views().readValues(tile.view->name);
        ViewChannel channel = defaultChannel(*tile.view);
        const DrawnPixels drawn = drawnPixels(renderer, *tile.view);
        ValueStatistics statistics = valueStatistics(values, channel, &drawn);
        // Below the tile's label only: the rectangle under it shows the frame's lower rows at the
        // tile's own scale (height - band rows of the tile for that share of the frame).
        int band = std::min(overviewLabelBand(tile), tile.height - 1);
        paintOverlayIn(image, {tile.x, tile.y + band, tile.width, tile.height - band}, values, width,
                       height - height * band / tile.height, channel, overlay, &drawn);
        char line[320];
        std::snprintf(line, sizeof(line), "overview tile %s (%s): NaN %ld, +Inf %ld, -Inf %ld, negative %ld; finite min "
                      "%.6g, max %.6g", tile.view->name.c_str(), describeChannel(*tile.view, channel).c_str(),
                     statistics.nan, statistics.positiveInfinity, statistics.negativeInfinity, statistics.negative,
                      statistics.min, statistics.max);
        counts.push_back(line);
    }
    return counts;
}

}  // namespace oasis
