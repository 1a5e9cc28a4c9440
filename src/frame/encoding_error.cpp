// Encoding error against the full layout: two deferred frames, their decoded normals and
// positions (the views' values), compared where both hold the same surface.
#include "frame/encoding_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/shared_constants.glsl"
#include "frame/renderer.h"

namespace oasis {
namespace {

struct DecodedFrame {
    std::vector<float> normal, position, info;  // view values: xyz length | xyz distance | power intensity flags
};

DecodedFrame decodedFrame(Renderer& renderer, const SceneSettings& scene, const GBufferLayout& layout) {
    renderer.configure(renderer.targets().width(), renderer.targets().height(), layout);
    renderer.setPipeline(PipelineKind::Deferred);
    renderer.renderFrame(scene);
    return {renderer.views().readValues("normal"), renderer.views().readValues("position"), renderer.views().readValues("info")};
}

}  // namespace

EncodingError measureEncodingError(Renderer& renderer, const SceneSettings& scene, const GBufferLayout& asked) {
    // The table's row, not the caller's reference: that may be the renderer's own, which
    // reconfiguring replaces.
    const GBufferLayout& layout = *findGBufferLayout(asked.name);
    if (layout.name == "full")
        throw std::invalid_argument("the encoding-error views compare a layout against full: choose standard or compact");
    const PipelineKind pipeline = renderer.pipeline();
    const std::string requested = renderer.paths().gbufferRequested;  // kept: a fallback still says so
    const DecodedFrame reference = decodedFrame(renderer, scene, *findGBufferLayout("full"));
    const DecodedFrame encoded = decodedFrame(renderer, scene, layout);
    renderer.setPipeline(pipeline);
    if (const GBufferLayout* asked = findGBufferLayout(requested); asked && asked->name != layout.name)
        renderer.configure(renderer.targets().width(), renderer.targets().height(), *asked);
    const FrameData& frame = renderer.lastFrame().setup.data;
    const double nearPlane = frame.depthRange.x, farPlane = frame.depthRange.y;
    EncodingError error;
    error.width = renderer.targets().width();
    error.height = renderer.targets().height();
    error.layout = layout.name;
    const size_t pixels = size_t(error.width) * size_t(error.height);
    const float none = std::numeric_limits<float>::quiet_NaN();
    error.normalDegrees.assign(pixels, none);
    error.positionUnits.assign(pixels, none);
    error.positionSteps.assign(pixels, none);
    for (size_t i = 0; i < pixels; ++i) {
        const float* infoFull = &reference.info[i * 4];
        const float* infoLayout = &encoded.info[i * 4];
        unsigned flags = unsigned(std::lround(infoFull[2]));
        if ((flags & OASIS_SURFACE_SKY) || unsigned(std::lround(infoLayout[2])) != flags) continue;
        glm::dvec3 nFull(reference.normal[i * 4], reference.normal[i * 4 + 1], reference.normal[i * 4 + 2]);
        glm::dvec3 nLayout(encoded.normal[i * 4], encoded.normal[i * 4 + 1], encoded.normal[i * 4 + 2]);
        glm::dvec3 pFull(reference.position[i * 4], reference.position[i * 4 + 1], reference.position[i * 4 + 2]);
        glm::dvec3 pLayout(encoded.position[i * 4], encoded.position[i * 4 + 1], encoded.position[i * 4 + 2]);
        // atan2 of the cross and dot products keeps the small angles acos rounds away.
        double angle = std::atan2(glm::length(glm::cross(nFull, nLayout)), glm::dot(nFull, nLayout));
        error.normalDegrees[i] = float(glm::degrees(angle));
        double distance = glm::length(pFull - pLayout);
        error.positionUnits[i] = float(distance);
        error.positionSteps[i] = float(distance / depthStepAt(*renderer.paths().depth, glm::length(pFull), nearPlane, farPlane));
        ++error.surfaces;
    }
    return error;
}

ErrorSummary summarizeError(const std::vector<float>& values) {
    std::vector<float> finite;
    for (float v : values)
        if (std::isfinite(v)) finite.push_back(v);
    ErrorSummary summary;
    summary.count = long(finite.size());
    if (finite.empty()) return summary;
    std::sort(finite.begin(), finite.end());
    summary.median = finite[finite.size() / 2];
    summary.p99 = finite[std::min(finite.size() - 1, size_t(double(finite.size()) * 0.99))];
    summary.max = finite.back();
    return summary;
}

const std::vector<EncodingErrorView>& encodingErrorViews() {
    static const std::vector<EncodingErrorView> views = {
        {"normal-error", "the angle between the layout's decoded normal and full's, in degrees", &EncodingError::normalDegrees},
        {"position-error", "the distance between the layout's position (stored or rebuilt from depth) and full's, in world units",
         &EncodingError::positionUnits},
        {"position-error-steps", "the same distance in steps of the stored depth at that distance (D24: d^2 (f-n) / (f n 2^24))",
         &EncodingError::positionSteps},
    };
    return views;
}

std::string encodingErrorViewNames() {
    std::string names;
    for (const EncodingErrorView& view : encodingErrorViews()) names += (names.empty() ? "" : ", ") + view.name;
    return names;
}

const EncodingErrorView* findEncodingErrorView(const std::string& name) {
    for (const EncodingErrorView& view : encodingErrorViews())
        if (view.name == name) return &view;
    return nullptr;
}

}  // namespace oasis
