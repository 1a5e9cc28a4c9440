// The plant atlas: interpretation path choice, segments per variant, one draw into RGBA8.
#include "render/plant_atlas.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "common/shared_constants.glsl"

namespace oasis {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    glFinish();
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// How a cell's plant fills it: the root at the bottom centre, OASIS_PLANT_ROOT_V of the cell above
// the bottom edge, and the plant as large as fits inside that margin on every side. A billboard
// then stands its root on the ground without knowing the plant's shape.
struct CellFit {
    glm::vec2 centre{0.0f};
    float scale = 1.0f;
    float maxDistance = 1.0f;
};

CellFit fitSegments(const std::vector<Segment2D>& segments) {
    CellFit fit;
    if (segments.empty()) return fit;
    float highest = 1e-6f, widest = 1e-6f;
    for (const Segment2D& s : segments) {
        highest = std::max({highest, s.start.y, s.end.y});
        widest = std::max({widest, std::fabs(s.start.x), std::fabs(s.end.x)});
        fit.maxDistance = std::max(fit.maxDistance, s.distanceFromRoot + 1.0f);
    }
    // In the cell's clip space the root sits at y = -1 + 2m and the plant may reach 1 - 2m.
    const float margin = float(OASIS_PLANT_ROOT_V), usable = 1.0f - 2.0f * margin;
    fit.scale = std::min(2.0f * usable / highest, usable / widest);
    fit.centre = {0.0f, usable / fit.scale};
    return fit;
}

// Segment2D as instanced vertex attributes: start, end, distanceFromRoot (depth is not drawn).
void bindSegmentAttributes(GLuint buffer) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    const GLsizei stride = sizeof(Segment2D);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, (const void*)offsetof(Segment2D, start));
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride, (const void*)offsetof(Segment2D, end));
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride, (const void*)offsetof(Segment2D, distanceFromRoot));
    for (GLuint attribute = 0; attribute < 3; ++attribute) {
        glEnableVertexAttribArray(attribute);
        glVertexAttribDivisor(attribute, 1);
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

TurtleProgram programFor(const PlantAtlasVariant& variant, const PlantPreset& preset) {
    return encodeTurtleProgram(rewrite(preset.system, variant.iterations));
}

const PlantPreset& presetOf(const PlantAtlasVariant& variant) {
    const PlantPreset* preset = findPlantPreset(variant.preset);
    if (!preset) throw std::logic_error("plant atlas variant names no preset: " + variant.preset);
    return *preset;
}

}  // namespace

const char* plantInterpretationName(PlantInterpretation path) {
    return path == PlantInterpretation::Gpu ? "gpu" : "cpu";
}

PlantInterpretation choosePlantInterpretation(const gl::Capabilities& caps, bool forceCpu, std::string& reason) {
    if (forceCpu) {
        reason = "cpu (forced with --no-compute)";
        return PlantInterpretation::Cpu;
    }
    std::string why;
    bool compute = caps.computeAvailable(&why);
    reason = (compute ? "gpu (" : "cpu (") + why + ")";
    return compute ? PlantInterpretation::Gpu : PlantInterpretation::Cpu;
}

const std::vector<PlantAtlasVariant>& plantAtlasVariants() {
    static const std::vector<PlantAtlasVariant> variants = [] {
        std::vector<PlantAtlasVariant> table;
        for (int fewer : {0, 1})
            for (const PlantPreset& preset : plantPresets())
                table.push_back({preset.name, preset.system.iterations - fewer});
        return table;
    }();
    return variants;
}

PlantAtlas::PlantAtlas(ShaderLibrary& shaders, PlantInterpretation path, int cellSize)
    : path_(path), cellSize_(cellSize) {
    gl::DebugGroup group("PlantAtlas");
    const auto& variants = plantAtlasVariants();
    columns_ = int(plantPresets().size());
    rows_ = int((variants.size() + size_t(columns_) - 1) / size_t(columns_));
    if (variants.size() > size_t(OASIS_PLANT_MAX_CELLS))
        throw std::logic_error("the plant atlas has more cells than the billboards' bounds array holds (OASIS_PLANT_MAX_CELLS)");
    Clock::time_point start = Clock::now();
    std::vector<SegmentBuffer> buffers;
    GpuTurtleInterpreter gpu(shaders);
    for (const PlantAtlasVariant& variant : variants) {
        const PlantPreset& preset = presetOf(variant);
        TurtleProgram program = programFor(variant, preset);
        if (path_ == PlantInterpretation::Gpu)
            buffers.push_back(gpu.interpret(program, preset.system.angleDegrees));
        else
            buffers.push_back(uploadSegments(interpretTurtleByComposition(program, preset.system.angleDegrees)));
    }
    interpretMs_ = millisecondsSince(start);
    // Both paths fit the cells from the segments in the buffers (a read-back on the GPU path).
    for (const SegmentBuffer& buffer : buffers) segments_.push_back(readSegments(buffer));
    draw(shaders, buffers);
    measureDrawnBounds();
    totalMs_ = millisecondsSince(start);
}

void PlantAtlas::draw(ShaderLibrary& shaders, const std::vector<SegmentBuffer>& buffers) {
    // Nearest filtering of level 0, like every target the debug views sample; the billboards read
    // the mipmaps through their own sampler (src/render/vegetation_buffers.h).
    texture_ = gl::createTargetTexture("plant atlas", GL_RGBA8, width(), height(), kMipLevels);
    gl::Framebuffer framebuffer = gl::createFramebuffer("plant atlas: PlantAtlas");
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.name());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_.name(), 0);
    const GLfloat transparent[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, transparent);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    GLuint program = shaders.program("plant.atlas");
    glUseProgram(program);
    for (size_t i = 0; i < buffers.size(); ++i) drawCell(program, i, buffers[i]);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    buildCoverageMips();
}

void PlantAtlas::buildCoverageMips() {
    // The transparent background is black, so the box-filtered levels hold premultiplied colour;
    // each cell's alpha is then scaled per level so the billboards' fixed threshold keeps the
    // coverage it has at level 0 (render/coverage_mips.h).
    std::vector<MipImage> levels = boxFilteredMips(readLevel(0), kMipLevels);
    preserveCoverage(levels, cellSize_, float(OASIS_PLANT_ALPHA_THRESHOLD));
    glBindTexture(GL_TEXTURE_2D, texture_.name());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (size_t level = 1; level < levels.size(); ++level)
        glTexSubImage2D(GL_TEXTURE_2D, GLint(level), 0, 0, levels[level].width, levels[level].height, GL_RGBA,
                        GL_UNSIGNED_BYTE, levels[level].rgba.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, 0);
}

MipImage PlantAtlas::readLevel(int level) const {
    MipImage image;
    image.width = std::max(1, width() >> level);
    image.height = std::max(1, height() >> level);
    image.rgba.resize(size_t(image.width) * size_t(image.height) * 4);
    gl::Framebuffer framebuffer = gl::createFramebuffer("plant atlas: level read-back");
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.name());
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_.name(), level);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return image;
}

void PlantAtlas::drawCell(GLuint program, size_t variant, const SegmentBuffer& buffer) {
    if (buffer.count == 0) return;
    CellFit fit = fitSegments(segments_[variant]);
    glUniform2f(glGetUniformLocation(program, "plantCentre"), fit.centre.x, fit.centre.y);
    glUniform1f(glGetUniformLocation(program, "plantScale"), fit.scale);
    glUniform1f(glGetUniformLocation(program, "maxDistance"), fit.maxDistance);
    glUniform1f(glGetUniformLocation(program, "texelSize"), 2.0f / float(cellSize_));
    // GL rows run bottom-up; cells are numbered from the top row.
    glViewport(cellX(variant), height() - cellY(variant) - cellSize_, cellSize_, cellSize_);
    gl::VertexArray vertexArray = gl::createVertexArray("plant segments");
    glBindVertexArray(vertexArray.name());
    bindSegmentAttributes(buffer.buffer.name());
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(buffer.count));
    glBindVertexArray(0);
}

void PlantAtlas::measureDrawnBounds() {
    // A texel reaches a sample only through bilinear filtering, i.e. within 1.5 texels of its
    // centre at its level; a blend (bilinear, or trilinear between levels) of values all below
    // the threshold (the same at every level) stays below it. Two levels of 255 below the threshold absorb the filter's
    // fixed-point rounding.
    const int minimumByte = int(std::floor(OASIS_PLANT_ALPHA_THRESHOLD * 255.0)) - 2;
    const size_t cells = variantCount();
    std::vector<glm::vec4> box(cells, glm::vec4(1.0f, 1.0f, 0.0f, 0.0f));  // empty: min > max
    gl::Framebuffer framebuffer = gl::createFramebuffer("plant atlas: drawn-bounds read-back");
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.name());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (int level = 0; level < kMipLevels; ++level) {
        const int w = std::max(1, width() >> level), h = std::max(1, height() >> level);
        const float texel = float(1 << level);  // level-0 texels per texel of this level
        std::vector<unsigned char> rgba(size_t(w) * size_t(h) * 4);
        glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_.name(), level);
        glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        for (size_t cell = 0; cell < cells; ++cell) {
            // The cell in level-0 texels, GL rows (bottom-up); cells are numbered from the top.
            const float x0 = float(cellX(cell)), y0 = float(height() - cellY(cell) - cellSize_);
            const float size = float(cellSize_);
            // This level's texels whose footprint reaches the cell: one texel of border each side.
            const int tx0 = std::max(0, int(std::floor(x0 / texel)) - 1), tx1 = std::min(w - 1, int((x0 + size) / texel));
            const int ty0 = std::max(0, int(std::floor(y0 / texel)) - 1), ty1 = std::min(h - 1, int((y0 + size) / texel));
            for (int y = ty0; y <= ty1; ++y)
                for (int x = tx0; x <= tx1; ++x) {
                    if (rgba[(size_t(y) * size_t(w) + size_t(x)) * 4 + 3] < minimumByte) continue;
                    glm::vec4& b = box[cell];
                    b.x = std::min(b.x, ((float(x) - 0.5f) * texel - x0) / size);
                    b.y = std::min(b.y, ((float(y) - 0.5f) * texel - y0) / size);
                    b.z = std::max(b.z, ((float(x) + 1.5f) * texel - x0) / size);
                    b.w = std::max(b.w, ((float(y) + 1.5f) * texel - y0) / size);
                }
        }
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    drawnBounds_.clear();
    for (glm::vec4 b : box) {
        if (b.x > b.z) b = glm::vec4(0.0f);  // nothing drawn: a box of no area
        drawnBounds_.push_back(glm::clamp(b, glm::vec4(0.0f), glm::vec4(1.0f)));
    }
}

Image PlantAtlas::read() const {
    Image image(width(), height());
    gl::Framebuffer framebuffer = gl::createFramebuffer("plant atlas read-back");
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.name());
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_.name(), 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    image.flipRows();
    return image;
}

}  // namespace oasis
