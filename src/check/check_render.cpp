// Rendering a check case in this process (check/check_render.h).
#include "check/check_render.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <cstdio>
#include <stdexcept>

#include "cli/options.h"
#include "check/case_geometry.h"
#include "check/check_buffers.h"
#include "commands/headless_commands.h"
#include "commands/provenance.h"
#include "commands/session.h"
#include "context/gl_context.h"
#include "render/gbuffer_layout.h"

namespace oasis {
namespace {

// The targets a pass can leave, through the views that read them (the same on every tier).
struct TargetView {
    const char* view;   // the view that reads it
    const char* label;  // what the report calls it
    Target target;      // what the passes declare they write
};
const TargetView kTargetViews[] = {
    {"albedo", "Albedo", Target::Albedo}, {"normal", "Normal", Target::Normal},
    {"position", "Position", Target::Position}, {"info", "Info", Target::Info},
    {"depth", "DepthStencil (depth)", Target::DepthStencil}, {"stencil", "DepthStencil (stencil)", Target::DepthStencil},
    {"radiance", "Radiance", Target::Radiance}, {"reflection-raw", "Reflection", Target::Reflection},
    {"final", "Final", Target::Final}};

Options caseOptions(const std::vector<std::string>& arguments) {
    std::vector<std::string> command = {"render"};
    command.insert(command.end(), arguments.begin(), arguments.end());
    for (const char* extra : {"--legend", "off"}) command.push_back(extra);
    ParseResult parsed = parseCommandLine(command);
    if (!parsed.ok) throw std::runtime_error("a check case's arguments are refused: " + parsed.error);
    return parsed.options;
}

// The session's own report lines (its fallbacks) would bury the check's progress: stderr goes to a
// scratch file while a case renders, and comes back afterwards.
#ifdef __EMSCRIPTEN__
// In the page stderr is the browser's console (emscripten's TTY, no descriptor to swap): the
// sessions' report lines go there, out of the check's report.
class QuietStderr {};
#else
class QuietStderr {
public:
    QuietStderr() {
        std::fflush(stderr);
        saved_ = dup(STDERR_FILENO);
        scratch_ = std::tmpfile();
        if (saved_ >= 0 && scratch_) dup2(fileno(scratch_), STDERR_FILENO);
    }
    ~QuietStderr() {
        std::fflush(stderr);
        if (saved_ >= 0) {
            dup2(saved_, STDERR_FILENO);
            close(saved_);
        }
        if (scratch_) std::fclose(scratch_);
    }

private:
    int saved_ = -1;
    std::FILE* scratch_ = nullptr;
};
#endif

// Whose limit a path not taken is: the driver's own answer (ignoring --force) decides.
std::string limitOf(bool driverHasIt) { return driverHasIt ? "forced tier" : "driver"; }

// Why the session did not take a path the options ask for (and whose limit), or "".
std::string pathNotTaken(const Options& options, const RenderSession& session, bool gpuPlants, std::string& limitedBy) {
    const Renderer& renderer = *session.renderer;
    const SceneOptions& scene = options.scene;
    const gl::Capabilities& caps = session.caps;
    if (scene.lightsPath && renderer.paths().lights.path != *scene.lightsPath) {
        limitedBy = limitOf(caps.driverHasSsbo());
        return "lights path " + std::string(lightsPathName(*scene.lightsPath)) + " not taken: " + renderer.paths().lights.reason;
    }
    if (scene.lightMethod && options.pipeline == PipelineKind::Deferred && renderer.paths().lightMethod.method != *scene.lightMethod) {
        limitedBy = limitOf(caps.driverHasCompute() && caps.driverHasSsbo());
        return "light method " + std::string(lightMethodName(*scene.lightMethod)) + " not taken: " +
               renderer.paths().lightMethod.reason;
    }
    if (gpuPlants && session.plantPath != PlantInterpretation::Gpu) {
        limitedBy = limitOf(caps.driverHasCompute() && caps.driverHasSsbo());
        return "plants on the GPU not taken: " + session.plantPathReason;
    }
    if (options.stencilView && renderer.views().stencilPath() != *options.stencilView) {
        limitedBy = limitOf(caps.driverHasStencilTexturing());
        return std::string("stencil view ") + stencilViewPathName(*options.stencilView) + " not taken: " +
               session.stencilPathReason;
    }
    if (scene.depth == "reversed-z" && renderer.paths().depthFellBack) {
        limitedBy = limitOf(caps.driverHasClipControl());
        return "reversed-z depth not taken: " + renderer.paths().depthReason;
    }
    return {};
}

// The shading oracle over the frame just drawn, and the frame's pixels split into edges and
// interiors from the same inputs. Inputs that cannot be read at all leave every sampled pixel out,
// saying why, and no split: the case is then judged by its whole images alone.
ShadingOracle oracleOf(Renderer& renderer, std::vector<uint8_t>& pixelClasses) {
    try {
        OracleInputs inputs = readOracleInputs(renderer);
        pixelClasses = classifyPixels(caseGeometry(inputs));
        return runShadingOracle(renderer, inputs);
    } catch (const std::exception& error) {
        ShadingOracle oracle;
        oracle.ran = true;
        oracle.bound = shadingOracleBound();
        oracle.verdict = "none";
        oracle.leftOut.push_back({std::string("inputs unreadable: ") + error.what(), 0});
        return oracle;
    }
}

// Whether a buffer's per-pixel check counts differently in the two paths at a pixel of `where` (a
// check one path lacks counts 0 there: that path has no such buffer to get wrong); which, and at
// how many pixels.
bool pixelCheckDiffers(const PassSnapshot& reference, const PassSnapshot& candidate, const std::vector<bool>& where,
                       std::string& name, long& pixels) {
    std::vector<std::string> names;
    for (const PassSnapshot* side : {&reference, &candidate})
        for (const auto& check : side->pixelChecks)
            if (std::find(names.begin(), names.end(), check.first) == names.end()) names.push_back(check.first);
    auto valuesOf = [](const PassSnapshot& side, const std::string& wanted) -> const std::vector<float>* {
        for (const auto& [label, values] : side.pixelChecks)
            if (label == wanted) return &values;
        return nullptr;
    };
    for (const std::string& wanted : names) {
        const std::vector<float>* a = valuesOf(reference, wanted);
        const std::vector<float>* b = valuesOf(candidate, wanted);
        size_t count = std::max(a ? a->size() : 0, b ? b->size() : 0);
        if (a && b && a->size() != b->size()) continue;  // not the same pixels: nothing to compare
        pixels = 0;
        for (size_t p = 0; p < count; ++p) {
            if (p < where.size() && !where[p]) continue;
            pixels += (a ? (*a)[p] : 0.0f) != (b ? (*b)[p] : 0.0f);
        }
        if (pixels > 0) {
            name = wanted;
            return true;
        }
    }
    return false;
}

}  // namespace

CaseFrame renderCaseFrame(const std::vector<std::string>& arguments, bool gpuPlants, bool quiet) {
    Options options = caseOptions(arguments);
    CaseFrame frame;
    std::optional<QuietStderr> quieted;
    if (quiet) quieted.emplace();
    std::unique_ptr<HeadlessContext> context;
    try {
        context = std::make_unique<HeadlessContext>(maxGlVersionFor(options.scene));
    } catch (const std::exception& error) {
        frame.skipReason = std::string("no context for it: ") + error.what();
        frame.limitedBy = "driver";
        return frame;
    }
    RenderSession session(options);
    ContextInfo info = queryContextInfo();
    frame.context = {info.version, info.glslVersion, info.renderer, session.caps.es ? "OpenGL ES" : "OpenGL"};
    if (std::string why = pathNotTaken(options, session, gpuPlants, frame.limitedBy); !why.empty()) {
        frame.skipReason = why;
        return frame;
    }
    Renderer& renderer = *session.renderer;
    // The renderer's own layout fallback: the case runs on the layout drawn, and says which and why.
    if (renderer.paths().gbufferFellBack) frame.drawnWith = "drawn with gbuffer " + renderer.paths().gbufferReason;
    std::FILE* sink = std::fopen("/dev/null", "w");
    const bool oracle = options.view == "final" && options.stopBefore.empty();
    frame.image = renderRequestedImage(options, session, sink ? sink : stderr,
                                       oracle ? oracleReads(renderer.targets().layout()) : std::vector<Resource>{});
    if (sink) std::fclose(sink);
    if (oracle) frame.oracle = oracleOf(renderer, frame.pixelClasses);
    frame.provenance = provenanceTexts(pictureProvenance(options, options.view, pipelineName(options.pipeline),
                                                         frame.image.height, frame.image.height));
    frame.rendered = true;
    return frame;
}

CheckReport driverReport(const std::vector<std::string>& arguments) {
    Options options = caseOptions(arguments);
    CheckReport report;
    HeadlessContext context(maxGlVersionFor(options.scene));
    RenderSession session(options, RenderSession::Shaders::CapabilitiesOnly);
    const gl::Capabilities& caps = session.caps;
    // The context's own strings: GL_VENDOR and GL_RENDERER natively; in a browser, whose GL_RENDERER
    // is masked ("WebKit WebGL"), WEBGL_debug_renderer_info's where it is offered (web_context.cpp).
    ContextInfo info = queryContextInfo();
    report.vendor = info.vendor.empty() ? caps.vendor : info.vendor;
    report.renderer = info.renderer.empty() ? caps.renderer : info.renderer;
    report.glVersion = caps.version;
    report.glslVersion = caps.glslVersion;
    report.api = caps.es ? "OpenGL ES" : "OpenGL";
    for (const gl::FeatureReport& feature : session.features())
        report.caps.push_back({feature.name, feature.available, feature.used, feature.reason, feature.limitedBy});
    for (const gl::WorkaroundState& state : session.workarounds.rows)
        if (state.applied) report.workarounds.push_back({state.name, state.why});
    return report;
}

std::vector<PassSnapshot> renderPassByPass(const std::vector<std::string>& arguments, bool quiet) {
    Options options = caseOptions(arguments);
    std::optional<QuietStderr> quieted;
    if (quiet) quieted.emplace();
    HeadlessContext context(maxGlVersionFor(options.scene));
    RenderSession session(options);
    Renderer& renderer = *session.renderer;
    renderer.setPipeline(options.pipeline);
    Pipeline passList(options.pipeline);  // GL-free: the passes in order, with their declarations
    const auto& passes = passList.passes();
    std::set<Target> written;  // what the frame has written so far: the rest holds no value yet
    std::vector<PassSnapshot> snapshots;
    for (size_t k = 0; k < passes.size(); ++k) {
        // The frame after pass k is the frame stopped before pass k + 1 (a pass that does not run
        // this frame leaves the targets as they were).
        renderer.renderFrame(session.scene, k + 1 < passes.size() ? passes[k + 1]->name() : std::string());
        // The buffers the renderer uploaded before the first pass, once: the search's first step.
        if (k == 0) snapshots.push_back(snapshotFrameInputs(renderer));
        std::vector<Resource> writes = passes[k]->writes(renderer.lastFrame().setup);
        for (const Resource& resource : writes)
            if (const Target* target = std::get_if<Target>(&resource)) written.insert(*target);
        PassSnapshot snapshot{passes[k]->name(), {}};
        // Read before the views, which may refill the G-buffer the tile lists are checked against;
        // the renderer's own pass, which holds the buffers it wrote (the list here is GL-free).
        snapshotWrittenBuffers(renderer, *renderer.lastFrame().pipeline.passes()[k], writes, snapshot);
        for (const TargetView& target : kTargetViews)
            if (written.count(target.target)) snapshot.targets.push_back({target.label, renderer.views().readValues(target.view)});
        snapshots.push_back(std::move(snapshot));
    }
    return snapshots;
}

bool firstDivergence(const std::vector<PassSnapshot>& reference, const std::vector<PassSnapshot>& candidate, int level,
                     const std::vector<bool>& where, Divergence& found) {
    for (size_t k = 0; k < reference.size() && k < candidate.size(); ++k) {
        if (reference[k].pass != candidate[k].pass) break;  // the lists part: nothing more to compare
        // What the pass wrote of the buffers first: the targets of the passes that read them follow.
        for (const BufferSnapshot& a : reference[k].buffers) {
            auto other = std::find_if(candidate[k].buffers.begin(), candidate[k].buffers.end(),
                                      [&](const BufferSnapshot& b) { return b.name == a.name; });
            if (other == candidate[k].buffers.end() || other->stride != a.stride) continue;
            if (long entries = bufferDifferences(a, *other, level); entries > 0) {
                found = {reference[k].pass, a.name, entries};
                return true;
            }
        }
        std::string buffer;
        if (long pixels = 0; pixelCheckDiffers(reference[k], candidate[k], where, buffer, pixels)) {
            found = {reference[k].pass, buffer, pixels};
            return true;
        }
        for (const auto& [label, a] : reference[k].targets) {
            auto other = std::find_if(candidate[k].targets.begin(), candidate[k].targets.end(),
                                      [&name = label](const auto& target) { return target.first == name; });
            if (other == candidate[k].targets.end()) continue;
            const std::vector<float>& b = other->second;
            if (a.size() != b.size()) continue;
            long pixels = 0;
            for (size_t p = 0; p + 3 < a.size(); p += 4) {
                if (p / 4 < where.size() && !where[p / 4]) continue;
                bool differs = false;
                for (size_t c = 0; c < 4 && !differs; ++c) {
                    float x = a[p + c], y = b[p + c];
                    if (std::isnan(x) || std::isnan(y)) differs = std::isnan(x) != std::isnan(y);
                    else differs = std::fabs(x - y) > float(level) / 255.0f * std::max(1.0f, std::fabs(x));
                }
                pixels += differs;
            }
            if (pixels == 0) continue;
            found = {reference[k].pass, label, pixels};
            return true;
        }
    }
    return false;
}

}  // namespace oasis
