// A pipeline: the passes of a forward or deferred frame in order (frame/frame_assembly.cpp puts
// them there), run as the frame graph decides (frame/frame_graph.h). `oasis render --graph`
// prints them with what each reads and writes.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "frame/frame_graph.h"
#include "passes/pass.h"

namespace oasis {

enum class PipelineKind { Forward, Deferred };
const char* pipelineName(PipelineKind kind);
bool parsePipelineKind(const std::string& text, PipelineKind& out);

class Pipeline {
public:
    explicit Pipeline(PipelineKind kind);
    PipelineKind kind() const { return kind_; }
    // Runs the passes `graph` keeps (the frame's graph: its first steps are this pipeline's passes,
    // in order; the views' steps after them run as each view is drawn), up to its cut where a
    // stopped frame's graph is cut (cutAt, --stop-before). `afterEach` is called after every pass
    // that ran (to record or time it).
    void run(PassContext& context, const FrameGraph& graph,
             const std::function<void(const Pass&)>& afterEach = {}) const;
    bool hasPass(const std::string& name) const;
    std::string passNames() const;
    bool writes(const FrameSetup& frame, Target target) const;
    // The frame's graph: which passes run for `frame` and `sinks`, which are culled and why.
    FrameGraph graph(const FrameSetup& frame, const std::vector<Resource>& sinks = frameOutputs()) const;
    const std::vector<std::unique_ptr<Pass>>& passes() const { return passes_; }

private:
    PipelineKind kind_;
    std::vector<std::unique_ptr<Pass>> passes_;
};

// Runs a pass and, where frames are validated (frameValidation()), audits what it read
// (frame/input_audit.h) and the framebuffer it left bound against its declarations; throws
// std::logic_error on a pass that read or drew anything it did not declare.
void runValidated(Pass& pass, PassContext& context);
// Keeps in context.producedBuffers the buffers `pass` just wrote that it owns (Pass::ownBuffer),
// for the later passes that sample them.
void recordProducedBuffers(const Pass& pass, PassContext& context);

}  // namespace oasis
