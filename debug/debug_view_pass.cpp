// Debug views into the Display target.
#include "debug/debug_view_pass.h"

#include <algorithm>
#include <cmath>

#include "render/depth_stencil_readback.h"
#include "render/texture_units.h"

namespace oasis {

const char* stencilViewPathName(StencilViewPath path) {
    return path == StencilViewPath::Texturing ? "stencil-texturing" : "read-back";
}

void DebugViewPass::uploadStencilCopy(ShaderLibrary& shaders, const FrameTargets& targets, bool drawn) {
    int w = targets.width(), h = targets.height();
    // ES has no GL_STENCIL_INDEX read; without GL_NV_read_depth_stencil the stencil is drawn out.
    stencilBytes_ = readStencilRegion(shaders, targets, wholeDepthStencil(targets, drawn));
    if (!stencilCopy_ || stencilCopyWidth_ != w || stencilCopyHeight_ != h) {
        stencilCopy_ = gl::createTargetTexture("stencil read-back copy", GL_R8UI, w, h);
        stencilCopyWidth_ = w;
        stencilCopyHeight_ = h;
    }
    glBindTexture(GL_TEXTURE_2D, stencilCopy_.name());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RED_INTEGER, GL_UNSIGNED_BYTE, stencilBytes_.data());
}

void DebugViewPass::bindSource(PassContext& context, const DebugView& view, StencilViewPath stencilPath) {
    const FrameTargets& targets = context.targets;
    auto bind = [](int unit, GLuint texture) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, texture);
    };
    GLuint depthStencil = targets.texture(Target::DepthStencil);
    switch (view.source) {
        case ViewSource::Final: bind(kUnitSource, targets.texture(Target::Final)); break;
        case ViewSource::Reflection:
            // Written only at the water's pixels: the view reads the stencil's water mark with it.
            bind(kUnitSource, targets.texture(Target::Reflection));
            bindStencil(context, stencilPath);
            break;
        case ViewSource::Radiance: bind(kUnitSource, targets.texture(Target::Radiance)); break;
        case ViewSource::PlantAtlas: bind(kUnitSource, plantAtlasTexture_); break;
        case ViewSource::Vegetation:
            bind(kUnitSource, targets.texture(Target::Final));
            bindGBufferInputs(targets);
            break;
        // The G-buffer views decode through common/gbuffer.glsl: each samples what the table says
        // it reads in this layout (the compact layout: intensity in albedo, position from depth),
        // no more, as its pass declares (frame/view_pass.h).
        case ViewSource::Albedo:
        case ViewSource::Normal:
        case ViewSource::Position:
        case ViewSource::Info: {
            std::vector<Access> reads;
            for (const Resource& read : viewReads(view, targets.layout())) reads.push_back({read, Use::Sample});
            bindDeclaredInputs(reads, context);
            break;
        }
        case ViewSource::Depth:
            bind(kUnitDepth, depthStencil);
            glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
            break;
        case ViewSource::Stencil: bindStencil(context, stencilPath); break;
    }
}

void DebugViewPass::bindStencil(PassContext& context, StencilViewPath stencilPath) {
    const FrameTargets& targets = context.targets;
    glActiveTexture(GL_TEXTURE0 + kUnitStencil);
    if (stencilPath == StencilViewPath::ReadBack) {
        uploadStencilCopy(context.shaders, targets, context.drawDepthStencilReads);
        glActiveTexture(GL_TEXTURE0 + kUnitStencil);
        glBindTexture(GL_TEXTURE_2D, stencilCopy_.name());
    } else {
        glBindTexture(GL_TEXTURE_2D, targets.texture(Target::DepthStencil));
        glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_STENCIL_INDEX);
    }
}

// The views of Reflection show it inside the water only (debug_view.frag's sourceWaterOnly).
static void setSourceWaterOnly(GLuint program, const DebugView& view) {
    if (GLint waterOnly = glGetUniformLocation(program, "sourceWaterOnly"); waterOnly >= 0)
        glUniform1i(waterOnly, view.source == ViewSource::Reflection ? 1 : 0);
}

void DebugViewPass::drawTile(PassContext& context, const DebugView& view, StencilViewPath stencilPath,
                             int x, int y, int width, int height) {
    gl::DebugGroup group(("DebugView." + view.name).c_str());
    bindSource(context, view, stencilPath);
    glBindFramebuffer(GL_FRAMEBUFFER, context.targets.displayFramebuffer());
    glViewport(x, y, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    GLuint program = context.shaders.program(context.targets.layout().program(debugProgramName(view)));
    glUseProgram(program);
    if (GLint exposure = glGetUniformLocation(program, "viewExposure"); exposure >= 0)
        glUniform1f(exposure, std::exp2(exposureStops_));
    setSourceWaterOnly(program, view);
    context.geometry.drawFullscreenTriangle();
    restoreDepthStencilMode(view, stencilPath);
}

void DebugViewPass::restoreDepthStencilMode(const DebugView& view, StencilViewPath stencilPath) {
    bool stencilBound = view.source == ViewSource::Stencil || view.source == ViewSource::Reflection;
    if (stencilBound && stencilPath == StencilViewPath::Texturing) {
        // Leave the depth-stencil texture in its default mode for the depth view and the passes.
        glActiveTexture(GL_TEXTURE0 + kUnitStencil);
        glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
    }
}

std::vector<float> DebugViewPass::readValues(PassContext& context, const DebugView& view, StencilViewPath stencilPath) {
    gl::DebugGroup group((name() + ".values." + view.name).c_str());
    const FrameTargets& targets = context.targets;
    // The target first: making it binds a texture on the active unit, which would unbind a source.
    values_.bindForDrawing(targets.width(), targets.height());
    bindSource(context, view, stencilPath);
    glBindFramebuffer(GL_FRAMEBUFFER, values_.framebuffer());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    GLuint program = context.shaders.program(targets.layout().program(debugValuesProgramName(view)));
    glUseProgram(program);
    setSourceWaterOnly(program, view);
    context.geometry.drawFullscreenTriangle();
    restoreDepthStencilMode(view, stencilPath);
    return values_.read();
}

void DebugViewPass::drawView(PassContext& context, const DebugView& view, StencilViewPath stencilPath) {
    gl::DebugGroup group(name().c_str());
    drawTile(context, view, stencilPath, 0, 0, context.targets.width(), context.targets.height());
}

namespace {
std::pair<int, int> overviewGrid() {
    size_t views = debugViews().size();
    int columns = int(std::ceil(std::sqrt(double(views))));
    return {columns, int((views + size_t(columns) - 1) / size_t(columns))};
}
}  // namespace

std::pair<int, int> overviewMinimumSize() {
    constexpr int kMinimumCell = 4 + 2;  // a 4-pixel tile and its one-pixel gap on each side
    auto [columns, rows] = overviewGrid();
    return {columns * kMinimumCell, rows * kMinimumCell};
}

std::vector<OverviewTile> overviewTiles(int width, int height) {
    const auto& views = debugViews();
    auto [columns, rows] = overviewGrid();
    int cellWidth = width / columns, cellHeight = height / rows;
    std::vector<OverviewTile> tiles;
    for (size_t i = 0; i < views.size(); ++i) {
        int column = int(i) % columns, row = int(i) / columns;
        // One pixel gap between tiles keeps their edges apart.
        tiles.push_back({&views[i], column * cellWidth + 1, row * cellHeight + 1, std::max(1, cellWidth - 2),
                         std::max(1, cellHeight - 2)});
    }
    return tiles;
}

namespace {
bool labelled(const OverviewTile& tile) { return tile.height + 2 >= 24; }
float labelScale(const OverviewTile& tile) { return std::max(1.0f, float(tile.height + 2) / 200.0f); }
}  // namespace

int overviewLabelBand(const OverviewTile& tile) {
    return labelled(tile) ? int(std::ceil(3.0f + 19.0f * labelScale(tile))) : 0;
}

std::string overviewLabel(const OverviewTile& tile, const std::string& waterScene) {
    const DebugView& view = *tile.view;
    if (!readsSceneSurfaces(view) || view.source == ViewSource::Stencil) return view.name;
    std::string label = view.name + " (water: " + waterScene + ")";
    bool fits = (7.0f * float(label.size()) + 6.0f) * labelScale(tile) + 3.0f <= float(tile.width);
    return fits ? label : view.name;
}

void DebugViewPass::drawOverview(PassContext& context, StencilViewPath stencilPath, const std::string& waterScene) {
    gl::DebugGroup group((name() + ".overview").c_str());
    const FrameTargets& targets = context.targets;
    const std::vector<OverviewTile> tiles = overviewTiles(targets.width(), targets.height());

    glBindFramebuffer(GL_FRAMEBUFFER, targets.displayFramebuffer());
    glViewport(0, 0, targets.width(), targets.height());
    glClearColor(0.08f, 0.08f, 0.08f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    std::vector<Label> labels;
    for (const OverviewTile& tile : tiles) {
        drawTile(context, *tile.view, stencilPath, tile.x, targets.height() - tile.y - tile.height, tile.width,
                 tile.height);
        labels.push_back({overviewLabel(tile, waterScene), float(tile.x + 3), float(tile.y + 3)});
    }
    if (labelled(tiles.front())) {
        if (!labels_) labels_ = std::make_unique<LabelOverlay>();
        glBindFramebuffer(GL_FRAMEBUFFER, targets.displayFramebuffer());
        glViewport(0, 0, targets.width(), targets.height());
        labels_->draw(labels, targets.width(), targets.height(), labelScale(tiles.front()));
    }
}

}  // namespace oasis
