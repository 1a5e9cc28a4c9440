// The two pipelines: their frames assembled (frame/frame_assembly.h), run as the graph decides.
#include "frame/pipeline.h"

#include <algorithm>
#include <stdexcept>

#include "frame/frame_assembly.h"
#include "frame/input_audit.h"

namespace oasis {

const char* pipelineName(PipelineKind kind) { return kind == PipelineKind::Forward ? "forward" : "deferred"; }

bool parsePipelineKind(const std::string& text, PipelineKind& out) {
    if (text == "forward") { out = PipelineKind::Forward; return true; }
    if (text == "deferred") { out = PipelineKind::Deferred; return true; }
    return false;
}

Pipeline::Pipeline(PipelineKind kind)
    : kind_(kind), passes_(assembleFrame(kind == PipelineKind::Forward ? FrameOutput::ForwardFrame
                                                                      : FrameOutput::DeferredFrame)) {}

FrameGraph Pipeline::graph(const FrameSetup& frame, const std::vector<Resource>& sinks) const {
    std::vector<const Pass*> passes;
    for (const auto& pass : passes_) passes.push_back(pass.get());
    return buildFrameGraph(passes, frame, sinks, frameInputs());
}

void Pipeline::run(PassContext& context, const FrameGraph& frameGraph,
                   const std::function<void(const Pass&)>& afterEach) const {
    if (frameGraph.steps.size() < passes_.size())
        throw std::logic_error("Pipeline::run: the graph holds fewer steps than the pipeline has passes");
    gl::DebugGroup group(pipelineName(kind_));
    // The whole frame's graph decides what runs, also when it stops early: a stopped frame is the
    // whole frame's first passes.
    if (frameValidation() && !frameGraph.problems.empty())
        throw std::logic_error("the " + std::string(pipelineName(kind_)) + " frame is invalid: " +
                               frameGraph.problems.front());
    for (size_t k = 0; k < passes_.size(); ++k) {
        Pass* pass = passes_[k].get();
        if (frameGraph.steps[k].pass != pass) throw std::logic_error("Pipeline::run: a graph of another frame");
        if (frameGraph.steps[k].cut) break;
        if (!frameGraph.steps[k].runs) continue;
        OnlyWhereWaterIsSeen onlyWithWater(context, pass->reflectionWork());
        runValidated(*pass, context);  // at its declared scale (the reflection's maybe reduced)
        recordProducedBuffers(*pass, context);
        if (afterEach) afterEach(*pass);
    }
}

bool Pipeline::hasPass(const std::string& name) const {
    return std::any_of(passes_.begin(), passes_.end(), [&](const auto& pass) { return pass->name() == name; });
}

std::string Pipeline::passNames() const {
    std::string names;
    for (const auto& pass : passes_) names += (names.empty() ? "" : ", ") + pass->name();
    return names;
}

bool Pipeline::writes(const FrameSetup& frame, Target target) const {
    return std::any_of(passes_.begin(), passes_.end(), [&](const auto& pass) { return pass->writes(frame, target); });
}

void recordProducedBuffers(const Pass& pass, PassContext& context) {
    for (const Resource& written : pass.writes(context.frame)) {
        const Buffer* buffer = std::get_if<Buffer>(&written);
        GLuint name = buffer ? pass.ownBuffer(*buffer) : 0;
        if (name == 0) continue;
        auto& produced = context.producedBuffers;
        produced.erase(std::remove_if(produced.begin(), produced.end(), [&](const auto& made) { return made.first == *buffer; }),
                       produced.end());
        produced.emplace_back(*buffer, name);
    }
}

void runValidated(Pass& pass, PassContext& context) {
    if (!frameValidation()) {
        pass.run(context);
        return;
    }
    // Nothing bound going in: whatever is bound after the pass, the pass bound itself (and a pass
    // that drew without binding its outputs draws nowhere, which the pictures show). Likewise no
    // undeclared input left bound where it reads (InputAudit).
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    std::vector<Resource> bound;
    std::string problem;
    {
        InputAudit inputs(pass, context);
        recordBoundTargets(&bound);
        try {
            pass.run(context);
        } catch (...) {
            recordBoundTargets(nullptr);
            throw;
        }
        recordBoundTargets(nullptr);
        problem = inputs.undeclaredReads();
    }
    std::string drawn = auditBoundFramebuffer(pass, context);
    if (!drawn.empty()) problem += (problem.empty() ? "" : "; ") + drawn;
    std::string unbound = auditBoundTargets(pass, context, bound);
    if (!unbound.empty()) problem += (problem.empty() ? "" : "; ") + unbound;
    if (!problem.empty()) throw std::logic_error("frame validation: " + problem);
}

}  // namespace oasis
