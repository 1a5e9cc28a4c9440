// A pipeline: an ordered list of passes over the shared frame targets.
//   deferred: Clear(G-buffer) -> Terrain(G-buffer) -> Sky(G-buffer) -> Lighting -> Final
//   forward:  Clear(Final)    -> Terrain(shaded)   -> Sky(shaded)                -> Final
#pragma once
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
    void run(PassContext& context) const;
    bool writes(Target target) const;
    const std::vector<std::unique_ptr<Pass>>& passes() const { return passes_; }

private:
    PipelineKind kind_;
    std::vector<std::unique_ptr<Pass>> passes_;
};

}  // namespace oasis
