// The overview's view controls (render --view overview, the window's overview): each tile's
// values read at the frame's size, the overlay painted where the tile samples them (below its
// label), and each tile's counts, as the legend strip gives them under a single view.
#pragma once
#include <string>
#include <vector>

#include "frame/renderer.h"
#include "render/image.h"

namespace oasis {

// Paints `overlay` over the tiles of `image` (the overview of the renderer's last frame, as
// renderView drew it); returns one line of counts per tile.
std::vector<std::string> overlayOverviewTiles(Image& image, Renderer& renderer, unsigned overlay);

}  // namespace oasis
