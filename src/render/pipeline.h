// A pipeline: an ordered list of passes over the shared frame targets.
//   deferred: Clear(G) Terrain(G) Vegetation(G) Lighting LightVolumes WaterMask | ReflectionClear(G)
//             Terrain(G, mirrored) Vegetation(G, mirrored) Lighting(mirrored) LightVolumes(mirrored)
//             | WaterComposite [ToneMap]
//   forward:  Clear(Radiance) Terrain Vegetation Sky WaterMask | ReflectionClear Terrain(mirrored)
//             Vegetation(mirrored) Sky(mirrored) | WaterComposite [ToneMap]
// The passes between the bars run only with reflections on and the camera above the water; the
// light volumes only when there are point lights; ToneMap only where the tone map is not fused
// into the passes that write each pixel's colour last (FrameSetup::toneMapFused).
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "passes/pass.h"

namespace oasis {

enum class PipelineKind { Forward, Deferred };
const char* pipelineName(PipelineKind kind);
bool parsePipelineKind(const std::string& text, PipelineKind& out);

class Pipeline {
public:
    explicit Pipeline(PipelineKind kind);
    PipelineKind kind() const { return kind_; }
    // Runs the active passes in order; stops before the pass named `stopBefore` (empty: run all).
    // Returns false if `stopBefore` names no pass of this pipeline.
    // `afterEach` is called after every pass that ran (to record or time it).
    bool run(PassContext& context, const std::string& stopBefore = {},
             const std::function<void(const Pass&)>& afterEach = {}) const;
    bool hasPass(const std::string& name) const;
    std::string passNames() const;
    bool writes(Target target) const;
    const std::vector<std::unique_ptr<Pass>>& passes() const { return passes_; }

private:
    PipelineKind kind_;
    std::vector<std::unique_ptr<Pass>> passes_;
};

}  // namespace oasis
