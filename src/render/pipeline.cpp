// The two pipelines as pass lists.
#include "render/pipeline.h"

#include <algorithm>

#include "passes/clear_pass.h"
#include "passes/lighting_pass.h"
#include "passes/sky_pass.h"
#include "passes/terrain_pass.h"

namespace oasis {

const char* pipelineName(PipelineKind kind) { return kind == PipelineKind::Forward ? "forward" : "deferred"; }

bool parsePipelineKind(const std::string& text, PipelineKind& out) {
    if (text == "forward") { out = PipelineKind::Forward; return true; }
    if (text == "deferred") { out = PipelineKind::Deferred; return true; }
    return false;
}

Pipeline::Pipeline(PipelineKind kind) : kind_(kind) {
    if (kind == PipelineKind::Deferred) {
        passes_.push_back(std::make_unique<ClearPass>(SurfaceOutput::GBuffer));
        passes_.push_back(std::make_unique<TerrainPass>(SurfaceOutput::GBuffer));
        passes_.push_back(std::make_unique<SkyPass>(SurfaceOutput::GBuffer));
        passes_.push_back(std::make_unique<LightingPass>());
    } else {
        passes_.push_back(std::make_unique<ClearPass>(SurfaceOutput::Forward));
        passes_.push_back(std::make_unique<TerrainPass>(SurfaceOutput::Forward));
        passes_.push_back(std::make_unique<SkyPass>(SurfaceOutput::Forward));
    }
}

void Pipeline::run(PassContext& context) const {
    gl::DebugGroup group(pipelineName(kind_));
    for (const auto& pass : passes_) pass->run(context);
}

bool Pipeline::writes(Target target) const {
    return std::any_of(passes_.begin(), passes_.end(), [&](const auto& pass) {
        auto written = pass->writes();
        return std::find(written.begin(), written.end(), target) != written.end();
    });
}

}  // namespace oasis
