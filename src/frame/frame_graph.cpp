// Culling, validation and printing of the frame graph (frame/frame_graph.h).
#include "frame/frame_graph.h"

#include <algorithm>
#include <cstdlib>
#include <set>

namespace oasis {
namespace {

bool contains(const std::vector<Resource>& list, const Resource& resource) {
    return std::find(list.begin(), list.end(), resource) != list.end();
}

std::string joined(const std::vector<Resource>& resources) {
    std::string text;
    for (const Resource& resource : resources) text += (text.empty() ? "" : ", ") + resourceName(resource);
    return text;
}

// Names are identifiers and target names: nothing in them needs escaping but these two.
std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string jsonList(const std::vector<Resource>& resources) {
    std::string text = "[";
    for (size_t k = 0; k < resources.size(); ++k) text += (k ? ", " : "") + quoted(resourceName(resources[k]));
    return text + "]";
}

#ifdef NDEBUG
constexpr bool kDebugBuild = false;
#else
constexpr bool kDebugBuild = true;
#endif

bool gValidation = kDebugBuild || (std::getenv("OASIS_VALIDATE_FRAME") &&
                                   std::string(std::getenv("OASIS_VALIDATE_FRAME")) == "1");

}  // namespace

bool FrameGraph::runs(const std::string& passName) const {
    return std::any_of(steps.begin(), steps.end(),
                       [&](const GraphStep& step) { return step.runs && !step.cut && step.pass->name() == passName; });
}

std::vector<Resource> frameOutputs() {
    std::vector<Resource> outputs;
    for (Target target : {Target::Albedo, Target::Normal, Target::Position, Target::Info, Target::DepthStencil,
                          Target::Radiance, Target::Reflection, Target::Final})
        outputs.push_back(target);
    outputs.push_back(Buffer::ShadowMaps);
    outputs.push_back(Buffer::TerrainHeights);
    return outputs;
}

std::vector<Resource> everyResource() {
    std::vector<Resource> all = frameOutputs();
    all.push_back(Target::SceneDepth);
    all.push_back(Buffer::LightTiles);
    for (const Resource& input : frameInputs()) all.push_back(input);
    return all;
}

std::vector<Resource> frameInputs() { return {Buffer::LightList, Buffer::PlantInstances}; }

namespace {

// Back from what is `live` after the steps: a pass is needed when a later pass (or the sink) reads
// what it writes. Leaves in `live` what is read before the first step.
void cullBackFrom(FrameGraph& graph, const FrameSetup& frame, std::set<Resource>& live) {
    for (auto step = graph.steps.rbegin(); step != graph.steps.rend(); ++step) {
        live.insert(step->readAfter.begin(), step->readAfter.end());
        if (!step->pass->active(frame)) {
            step->culled = "off in this frame's settings";
            continue;
        }
        bool needed = std::any_of(step->writes.begin(), step->writes.end(),
                                  [&](const Resource& written) { return live.count(written) > 0; });
        if (!needed) {
            step->culled = step->writes.empty() ? "writes nothing"
                                                : "nothing later reads what it writes (" + joined(step->writes) + ")";
            continue;
        }
        step->runs = true;
        for (const Access& access : step->pass->accesses(frame))
            if (access.use == Use::Replace) live.erase(access.resource);
        for (const Resource& read : step->reads) live.insert(read);
    }
}

FrameGraph stepsOf(const std::vector<const Pass*>& passes, const FrameSetup& frame) {
    FrameGraph graph;
    for (const Pass* pass : passes) graph.steps.push_back(graphStep(*pass, frame));
    return graph;
}

}  // namespace

GraphStep graphStep(const Pass& pass, const FrameSetup& frame, bool afterFrame) {
    GraphStep step{&pass, pass.reads(frame), pass.writes(frame), false, ""};
    step.afterFrame = afterFrame;
    return step;
}

bool cutAt(FrameGraph& graph, const std::string& passName) {
    auto at = std::find_if(graph.steps.begin(), graph.steps.end(), [&](const GraphStep& step) {
        return !step.afterFrame && step.pass->name() == passName;
    });
    for (auto step = at; step != graph.steps.end(); ++step)
        if (!step->afterFrame) step->cut = true;
    return at != graph.steps.end();
}

FrameGraph withoutViewSteps(const FrameGraph& graph) {
    FrameGraph frame = graph;
    frame.steps.erase(std::remove_if(frame.steps.begin(), frame.steps.end(),
                                     [](const GraphStep& step) { return step.afterFrame; }),
                      frame.steps.end());
    return frame;
}

FrameGraph buildFrameGraph(const std::vector<const Pass*>& passes, const FrameSetup& frame,
                           const std::vector<Resource>& sinks, const std::vector<Resource>& inputs) {
    return buildFrameGraph(stepsOf(passes, frame).steps, frame, sinks, inputs);
}

FrameGraph buildFrameGraph(std::vector<GraphStep> steps, const FrameSetup& frame, const std::vector<Resource>& sinks,
                           const std::vector<Resource>& inputs) {
    FrameGraph graph;
    graph.steps = std::move(steps);
    graph.inputs = inputs;
    std::set<Resource> live(sinks.begin(), sinks.end());
    cullBackFrom(graph, frame, live);
    // Forward: every read of a running pass has a writer before it or is an input.
    std::vector<Resource> written = inputs;
    for (const GraphStep& step : graph.steps) {
        if (!step.runs) continue;
        for (const Resource& read : step.reads)
            if (!contains(written, read))
                graph.problems.push_back(step.pass->name() + " reads " + resourceName(read) +
                                         ", which no pass wrote before it");
        for (const Resource& write : step.writes)
            if (!contains(written, write)) written.push_back(write);
    }
    return graph;
}

namespace {

// Each buffer the running passes touch, in the order the frame first touches it, with its writers
// and readers: "# LightTiles  LightTilingPass -> LightingPass" (each pass's line above names the
// targets it reads and writes; a target's line here would repeat most of the frame).
std::string buffersText(const FrameGraph& graph) {
    struct Uses {
        Resource resource;
        std::vector<std::string> writers, readers;
    };
    std::vector<Uses> uses;
    auto usesOf = [&](const Resource& resource) -> Uses& {
        for (Uses& known : uses)
            if (known.resource == resource) return known;
        uses.push_back({resource, {}, {}});
        return uses.back();
    };
    for (const GraphStep& step : graph.steps) {
        if (!step.runs) continue;
        for (const Resource& read : step.reads) {
            if (!std::holds_alternative<Buffer>(read)) continue;
            Uses& entry = usesOf(read);
            if (entry.writers.empty() && contains(graph.inputs, read)) entry.writers.push_back(kFrameInputsStep);
            entry.readers.push_back(step.pass->name());
        }
        for (const Resource& write : step.writes)
            if (std::holds_alternative<Buffer>(write)) usesOf(write).writers.push_back(step.pass->name());
    }
    if (uses.empty()) return {};
    size_t column = 0;
    for (const Uses& known : uses) column = std::max(column, resourceName(known.resource).size());
    auto names = [](const std::vector<std::string>& list) {
        std::string text;
        for (const std::string& name : list) text += (text.empty() ? "" : ", ") + name;
        return text.empty() ? std::string("-") : text;
    };
    std::string text = "# buffers: written by -> read by (the passes that run)\n";
    for (const Uses& known : uses) {
        std::string name = resourceName(known.resource);
        text += "# " + name + std::string(column + 2 - name.size(), ' ') + names(known.writers) + " -> " +
                names(known.readers) + "\n";
    }
    return text;
}

}  // namespace

std::string frameGraphText(const FrameGraph& graph) {
    // One pass a line, its name in a column: "NAME  reads -> writes", or "NAME  culled: why".
    size_t column = 0;
    for (const GraphStep& step : graph.steps) column = std::max(column, step.pass->name().size());
    auto listed = [](const std::vector<Resource>& resources) {
        return resources.empty() ? std::string("-") : joined(resources);
    };
    std::string text, cutName;
    for (const GraphStep& step : graph.steps)
        if (step.cut && cutName.empty()) cutName = step.pass->name();
    bool views = false;
    for (const GraphStep& step : graph.steps) {
        if (step.afterFrame && !views) text += std::string(kViewStepsHeader) + "\n";
        views = views || step.afterFrame;
        const std::string& name = step.pass->name();
        text += name + std::string(column + 2 - name.size(), ' ');
        if (step.runs && step.cut)
            text += "cut: the frame stops before " + cutName + " (--stop-before)";
        else
            text += step.runs ? listed(step.reads) + " -> " + listed(step.writes) : "culled: " + step.culled;
        text += "\n";
    }
    for (const std::string& problem : graph.problems) text += "invalid: " + problem + "\n";
    return text + buffersText(graph);
}

std::string frameGraphJson(const FrameGraph& graph) {
    std::string json = "[";
    for (size_t k = 0; k < graph.steps.size(); ++k) {
        const GraphStep& step = graph.steps[k];
        json += std::string(k ? ",\n    " : "\n    ") + "{\"name\": " + quoted(step.pass->name()) +
                ", \"reads\": " + jsonList(step.reads) + ", \"writes\": " + jsonList(step.writes) +
                ", \"culled\": " + (step.runs ? "false" : "true") + ", \"reason\": " + quoted(step.culled) + "}";
    }
    return json + (graph.steps.empty() ? "]" : "\n  ]");
}

std::vector<Resource> targetsHolding(const FrameTargets& targets, GLint texture) {
    std::vector<Resource> found;
    if (texture == 0) return found;
    for (int divisor : {1, 2, 4})
        for (int t = 0; t < int(Target::Count); ++t)
            if (GLint(targets.heldTexture(Target(t), divisor)) == texture)
                found.push_back(targetAt(Target(t), divisor));
    return found;
}

bool frameValidation() { return gValidation; }
void setFrameValidation(bool on) { gValidation = on; }

std::string auditBoundFramebuffer(const Pass& pass, const PassContext& context) {
    GLint framebuffer = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    if (framebuffer == 0) return {};
    std::vector<Access> declared = pass.accesses(context.frame);
    auto declaresAttached = [&](const Resource& target, bool depth) {
        return std::any_of(declared.begin(), declared.end(), [&](const Access& access) {
            if (access.resource != target) return false;
            return depth ? access.use != Use::Sample : isWrite(access.use);
        });
    };
    // What a texture attached there is: the targets (at any scale: the reduced reflection's too)
    // that hold it now (several where the plan aliases them); none for the shadow maps' own.
    auto heldBy = [&](GLint texture) { return targetsHolding(context.targets, texture); };
    GLint maxAttachments = 0;
    glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &maxAttachments);
    std::string problems;
    auto check = [&](GLenum attachment, bool depth) {
        GLint type = GL_NONE, texture = 0;
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                                              &type);
        if (type != GL_TEXTURE) return;
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
                                              &texture);
        std::vector<Resource> held = heldBy(texture);
        if (!held.empty() &&
            std::none_of(held.begin(), held.end(), [&](const Resource& t) { return declaresAttached(t, depth); }))
            problems += (problems.empty() ? "" : "; ") + pass.name() + " draws into " + resourceName(held.front()) +
                        ", which it does not declare";
    };
    for (GLint k = 0; k < maxAttachments; ++k) check(GLenum(GL_COLOR_ATTACHMENT0 + k), false);
    check(GL_DEPTH_ATTACHMENT, true);
    return problems;
}

std::string auditBoundTargets(const Pass& pass, const PassContext& context, const std::vector<Resource>& bound) {
    std::vector<Access> declared = pass.accesses(context.frame);
    auto declares = [&](const Resource& target, bool (*use)(Use)) {
        return std::any_of(declared.begin(), declared.end(),
                           [&](const Access& access) { return access.resource == target && use(access.use); });
    };
    auto attaches = [](Use use) { return use != Use::Sample; };
    std::string problems;
    auto problem = [&](const std::string& text) { problems += (problems.empty() ? "" : "; ") + text; };
    for (const Resource& target : bound)
        if (!declares(target, attaches))
            problem(pass.name() + " binds " + resourceName(target) + " for drawing, which it does not declare");
    for (const Access& access : declared) {
        Target target;
        int divisor;
        if (!targetOf(access.resource, target, divisor) || !isWrite(access.use) ||
            !context.targets.layout().stores(target))
            continue;
        if (std::find(bound.begin(), bound.end(), access.resource) == bound.end())
            problem(pass.name() + " declares it writes " + resourceName(access.resource) + " but never binds it");
    }
    return problems;
}

}  // namespace oasis
