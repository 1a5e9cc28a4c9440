// DebugViewPass: draws one debug view, or the overview grid of all of them with their names,
// into the Display target. The stencil view has two paths: sampling the depth-stencil texture
// through stencil texturing, or reading the stencil back to the CPU and uploading it.
#pragma once
#include <memory>
#include <vector>

#include "debug/debug_views.h"
#include "debug/label_overlay.h"
#include "passes/pass.h"
#include "render/float_readback.h"

namespace oasis {

enum class StencilViewPath { Texturing, ReadBack };
const char* stencilViewPathName(StencilViewPath path);

// Where the overview draws each view of the table: a grid of about square tiles, row-major from
// the top left, one pixel of gap inside each tile's cell (x, y from the top).
struct OverviewTile {
    const DebugView* view;
    int x, y, width, height;
};
std::vector<OverviewTile> overviewTiles(int width, int height);
// The smallest frame whose overview tiles are at least 4x4 pixels (smaller ones would be a single
// colour): {width, height}.
std::pair<int, int> overviewMinimumSize();
// The rows at the top of a tile its label covers (ImGui's 13-pixel font at the tiles' scale, its
// padding, 3 pixels in from the corner); 0 when tiles are too small to be labelled. The render
// command's overlay leaves them unpainted so the names stay readable.
int overviewLabelBand(const OverviewTile& tile);
// A tile's label: the view's name, and for the tiles of the frame's surfaces the water scene they
// show ("albedo (water: direct)") where that fits in the tile (ImGui's font: 7 pixels a letter).
std::string overviewLabel(const OverviewTile& tile, const std::string& waterScene);

class DebugViewPass {
public:
    std::string name() const { return "DebugViewPass"; }

    void drawView(PassContext& context, const DebugView& view, StencilViewPath stencilPath);
    // The view's values (viewValue() of debug_view.frag) as RGBA floats, bottom row first.
    std::vector<float> readValues(PassContext& context, const DebugView& view, StencilViewPath stencilPath);
    // The grid of every view; the tiles of the frame's surfaces are labelled with `waterScene`
    // ("direct", "mirrored"), the scene they show under the water.
    void drawOverview(PassContext& context, StencilViewPath stencilPath, const std::string& waterScene);
    // The texture the atlas view shows (0: none, the view is black).
    void setPlantAtlasTexture(GLuint texture) { plantAtlasTexture_ = texture; }
    // The HDR views' exposure in stops: linear light times 2^stops before display.
    void setExposureStops(float stops) { exposureStops_ = stops; }
    float exposureStops() const { return exposureStops_; }

private:
    void drawTile(PassContext& context, const DebugView& view, StencilViewPath stencilPath,
                  int x, int y, int width, int height);
    void bindSource(PassContext& context, const DebugView& view, StencilViewPath stencilPath);
    void restoreDepthStencilMode(const DebugView& view, StencilViewPath stencilPath);
    void uploadStencilCopy(ShaderLibrary& shaders, const FrameTargets& targets, bool drawn);
    // The stencil on kUnitStencil (texturing, or a read-back copy), for the stencil view and the
    // water mask of the Reflection views.
    void bindStencil(PassContext& context, StencilViewPath stencilPath);

    GLuint plantAtlasTexture_ = 0;
    float exposureStops_ = 0.0f;
    FloatReadback values_;  // readValues' float target
    gl::Texture stencilCopy_;
    int stencilCopyWidth_ = 0, stencilCopyHeight_ = 0;
    std::vector<uint8_t> stencilBytes_;
    std::unique_ptr<LabelOverlay> labels_;
};

}  // namespace oasis
