// The plant atlas: at start-up every variant of the L-system preset table is interpreted into
// segments (on the GPU when the context has compute shaders, else on the CPU) and drawn once as
// brown-to-green branches (thick at the root, thin at the tips) into one RGBA8 texture with a
// transparent background, a cell per variant, with mip levels that keep the alpha test's coverage.
#pragma once
#include <string>
#include <glm/glm.hpp>
#include <vector>

#include "gl/capabilities.h"
#include "gl/objects.h"
#include "render/coverage_mips.h"
#include "render/image.h"
#include "render/plant_interpreter.h"
#include "render/shader_library.h"
#include "scene/lsystem.h"

namespace oasis {

enum class PlantInterpretation { Gpu, Cpu };
const char* plantInterpretationName(PlantInterpretation path);  // "gpu" | "cpu"

// GPU when the capabilities allow compute (shaders and SSBOs, not switched off by --force) and
// --no-compute is not given; `reason` says why.
PlantInterpretation choosePlantInterpretation(const gl::Capabilities& caps, bool forceCpu, std::string& reason);

// One cell of the atlas: a preset at an iteration count. Cells run left to right, top to bottom.
struct PlantAtlasVariant {
    std::string preset;
    int iterations;
};
// The table: every preset at its default iterations (top row) and one rewrite fewer (bottom row).
const std::vector<PlantAtlasVariant>& plantAtlasVariants();

class PlantAtlas {
public:
    static constexpr int kCellSize = 256;
    // Levels down to 8 texels a cell: below that neighbouring cells would bleed into each other.
    static constexpr int kMipLevels = 6;

    // Interprets and draws every variant; throws std::runtime_error if the GPU path fails.
    PlantAtlas(ShaderLibrary& shaders, PlantInterpretation path, int cellSize = kCellSize);

    GLuint texture() const { return texture_.name(); }
    PlantInterpretation path() const { return path_; }
    int width() const { return columns_ * cellSize_; }
    int height() const { return rows_ * cellSize_; }
    int cellSize() const { return cellSize_; }
    int columns() const { return columns_; }
    int rows() const { return rows_; }
    size_t variantCount() const { return segments_.size(); }
    // Top-left pixel of a variant's cell in the image read() returns (top row first).
    int cellX(size_t variant) const { return int(variant % size_t(columns_)) * cellSize_; }
    int cellY(size_t variant) const { return int(variant / size_t(columns_)) * cellSize_; }
    // Wall-clock start-up cost, each ended by glFinish: segments ready, then segments and drawing.
    double interpretMs() const { return interpretMs_; }
    double totalMs() const { return totalMs_; }
    // Each variant's segments as drawn (read back from the GPU on that path).
    const std::vector<std::vector<Segment2D>>& segments() const { return segments_; }
    // Each variant's drawn bounds in its cell, (u0, v0, u1, v1) in [0, 1] with v up (GL rows): the
    // union over every mip level of where a billboard's alpha test can pass (texels at or above
    // the threshold, widened by the bilinear footprint). The billboards are trimmed to it,
    // so the fragments a plant's empty corners would discard are never rasterised. Empty cells
    // get an empty box.
    const std::vector<glm::vec4>& drawnBounds() const { return drawnBounds_; }

    Image read() const;
    // One mip level as stored (GL rows, bottom-up): level 0 as drawn, the others box-filtered with
    // each cell's alpha scaled to keep its alpha-test coverage (render/coverage_mips.h).
    MipImage readLevel(int level) const;

private:
    void draw(ShaderLibrary& shaders, const std::vector<SegmentBuffer>& buffers);
    void drawCell(GLuint program, size_t variant, const SegmentBuffer& buffer);
    void buildCoverageMips();
    void measureDrawnBounds();

    PlantInterpretation path_;
    int cellSize_;
    int columns_ = 1, rows_ = 1;
    gl::Texture texture_;
    std::vector<std::vector<Segment2D>> segments_;
    std::vector<glm::vec4> drawnBounds_;
    double interpretMs_ = 0.0, totalMs_ = 0.0;
};

}  // namespace oasis
