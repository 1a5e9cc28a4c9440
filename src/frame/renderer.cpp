// Frame orchestration: upload the frame's uniforms, run the active pipeline, draw debug views.
#include "frame/renderer.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "debug/debug_views.h"
#include "frame/target_lifetimes.h"
#include "gl/capabilities.h"
#include "gl/frame_capture.h"
#include "passes/pass.h"
#include "render/texture_units.h"

namespace oasis {

// Where the frame block's second range begins: the frame's data for the reduced reflection's size,
// after the frame's own, at the context's uniform buffer offset alignment.
static GLintptr reducedReflectionFrameRange() {
    GLint alignment = 1;
    glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &alignment);
    alignment = std::max(alignment, 1);
    return (GLintptr(sizeof(FrameData)) + alignment - 1) / alignment * alignment;
}

Renderer::Renderer(ShaderLibrary& shaders, const SceneSettings& scene)
    : shaders_(shaders), geometry_(scene.grid) {
    registerDebugViewPrograms();  // the debug views' programs, which debug/ adds to the variant table
    const std::vector<std::string>& dialectDefines = shaders.dialect().defines;
    setWaterClipByClipDistance(std::find(dialectDefines.begin(), dialectDefines.end(), "OASIS_NO_CLIP_DISTANCE 1") ==
                               dialectDefines.end());
    shadowMaps_.setDepthClamp(std::find(dialectDefines.begin(), dialectDefines.end(), "OASIS_NO_DEPTH_CLAMP 1") ==
                              dialectDefines.end());
    // Two ranges: the frame's data, and the same for the reduced reflection's size.
    frameUniforms_ = gl::createBuffer("frame data (ubo): the frame's, the reduced reflection's");
    glBindBuffer(GL_UNIFORM_BUFFER, frameUniforms_.name());
    glBufferData(GL_UNIFORM_BUFFER, reducedReflectionFrameRange() + GLintptr(sizeof(FrameData)), nullptr,
                 GL_DYNAMIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);

    // Point lights: what the context offers decides the path and the UBO path's block size (a
    // session replaces the capabilities with its --force-aware report: setCapabilities).
    const gl::Capabilities caps = gl::measureCapabilities();
    RendererCapabilities& given = paths_.capabilities;
    given.ssbo.available = caps.ssboAvailable(&lights_.ssboMissingReason);
    given.ssbo.reason = lights_.ssboMissingReason;
    given.forcedLightsPath = scene.lights.path;
    given.forcedLightMethod = scene.lights.method;
    // The table's driver workarounds for this context; a session gives its request's set instead.
    given.workarounds = gl::resolveWorkarounds({}, caps.renderer, caps.version);
    GLint maxBlockSize = 16384, maxVertexBlocks = 12, maxFragmentBlocks = 12;
    glGetIntegerv(GL_MAX_UNIFORM_BLOCK_SIZE, &maxBlockSize);
    glGetIntegerv(GL_MAX_VERTEX_UNIFORM_BLOCKS, &maxVertexBlocks);
    glGetIntegerv(GL_MAX_FRAGMENT_UNIFORM_BLOCKS, &maxFragmentBlocks);
    paths_.uboLights = uboLightLayout(maxBlockSize, std::min(maxVertexBlocks, maxFragmentBlocks));
    chooseWaterBounds();
    lights_.list = gl::createBuffer("point lights");  // named by its path once a frame picks one
    lights_.count = gl::createBuffer("point light count");
    glBindBuffer(GL_UNIFORM_BUFFER, lights_.list.name());
    glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(std::max(kMaxLights, paths_.uboLights.maxLights()) * sizeof(PointLight)),
                 nullptr, GL_DYNAMIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, lights_.count.name());
    glBufferData(GL_UNIFORM_BUFFER, 16, nullptr, GL_DYNAMIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
    paths_.lights = chooseLightsPath(given.ssbo.available, scene.lights.path, lights_.ssboMissingReason);
    given.compute.available = caps.computeAvailable(&given.compute.reason);
    paths_.lightMethod = chooseLightMethod(given.compute.available, scene.lights.method, given.compute.reason,
                                          paths_.lights.path);
    // Reversed-z depth needs glClipControl; the session's report replaces this too (--force).
    given.clipControl.available = caps.clipControlAvailable(&given.clipControl.reason);
    given.readOnlyDepth.available = caps.readOnlyDepthAvailable(&given.readOnlyDepth.reason);
    given.depthStencilRead.available = caps.depthStencilReadAvailable(&given.depthStencilRead.reason);
    // The compact layout's RG16 target (OpenGL ES: EXT_texture_norm16); else configure takes standard.
    given.norm16Targets.available = caps.norm16TargetsAvailable(&given.norm16Targets.reason);
    setDepthConvention(standardDepthConvention());
}

// Uploads the frame's lights once and binds them for every path: as the SSBO list (sized to the
// count, for .length()), as the UBO block array, and the count for the other two paths.
void Renderer::uploadLights() {
    paths_.lightsDropped = frame_.lightsDropped;
    paths_.lightsDrawn = int(frame_.lights.size());
    if (lights_.labelledPath != frame_.lightsPath) {  // "point lights (ssbo)": what the shaders read it as
        gl::setLabel(lights_.list, std::string("point lights (") + lightsPathName(frame_.lightsPath) + ")");
        lights_.labelledPath = frame_.lightsPath;
    }
    GLsizeiptr bytes = GLsizeiptr(frame_.lights.size() * sizeof(PointLight));
    glBindBuffer(GL_UNIFORM_BUFFER, lights_.list.name());
    if (bytes > 0) glBufferSubData(GL_UNIFORM_BUFFER, 0, bytes, frame_.lights.data());
    const GLuint count[4] = {GLuint(frame_.lights.size()), 0, 0, 0};
    glBindBuffer(GL_UNIFORM_BUFFER, lights_.count.name());
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(count), count);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
    GLsizeiptr blockBytes = GLsizeiptr(paths_.uboLights.capacity) * GLsizeiptr(sizeof(PointLight));
    for (int k = 0; k < paths_.uboLights.blocks; ++k)
        glBindBufferRange(GL_UNIFORM_BUFFER, GLuint(kLightBlockFirstBinding + k), lights_.list.name(), k * blockBytes,
                          blockBytes);
    glBindBufferBase(GL_UNIFORM_BUFFER, kLightCountBlockBinding, lights_.count.name());
    if (paths_.capabilities.ssbo.available) {
        // .length() is the bound range's size over 32 bytes; an empty list binds an empty range.
        if (bytes > 0)
            glBindBufferRange(GL_SHADER_STORAGE_BUFFER, kLightStorageBinding, lights_.list.name(), 0, bytes);
        else
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightStorageBinding, 0);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightCountStorageBinding, lights_.count.name());
    }
}

void Renderer::configure(int width, int height, const GBufferLayout& layout) {
    // The layout a fallback put in use, asked for again (a resize): the request stands.
    const bool sameAsFallback = targets_ && paths_.gbufferFellBack && layout.name == targets_->layout().name;
    const GBufferLayout& requested = sameAsFallback ? *requested_.layout : layout;
    std::string reason;
    const GBufferLayout& use = chooseGBufferLayout(requested, reason);
    if (!targets_ || targets_->width() != width || targets_->height() != height || targets_->layout().name != use.name) {
        // Build the new targets before dropping the old: if allocation fails (too large, out of
        // memory) the renderer keeps working at its previous size, layout and reason.
        auto replacement = std::make_unique<FrameTargets>(use, *paths_.depth, width, height);
        targets_ = std::move(replacement);
        forgetGBuffer();
    }
    if (!sameAsFallback) requested_.layout = layout;
    paths_.gbuffer = &targets_->layout();
    paths_.gbufferRequested = requested_.layout->name;
    paths_.gbufferReason = std::move(reason);
    paths_.gbufferFellBack = use.name != requested_.layout->name;
}

PassContext Renderer::context() { return contextOver(*targets_, frame_); }

PassContext Renderer::contextOver(const FrameTargets& targets, const FrameSetup& frame) {
    // Another renderer of the same context may have bound its own maps there since.
    shadowMaps_.bind();
    PassContext context{targets, shaders_, geometry_, frame, plants_.buffers,
                        paths_.waterBoundsAvailable ? water_.bounds.name() : 0u, &shadowMaps_,
                        frame_.waterBounded ? water_.seen.name() : 0u};
    context.drawDepthStencilReads = !paths_.capabilities.depthStencilRead.available;
    context.depthClamp = shadowMaps_.depthClamp();  // the dialect's answer (OASIS_NO_DEPTH_CLAMP)
    context.flushBeforeComputeRead = paths_.capabilities.workarounds.has(gl::Workaround::FlushBeforeComputeRead);
    return context;
}

FrameConditions Renderer::frameConditions(const SceneSettings& scene, const std::string& stopBefore) const {
    FrameConditions conditions;
    conditions.depth = targets_->depth();
    conditions.casterDepth = shadowMaps_.depthClamp() ? ShadowCasterDepth::Clamped : ShadowCasterDepth::Contained;
    conditions.positionFromDepth = targets_->layout().positionFromDepth();
    conditions.waterBoundsAvailable = paths_.waterBoundsAvailable;
    conditions.readOnlyDepth = paths_.capabilities.readOnlyDepth.available;
    conditions.lightsPath = paths_.lights.path;
    conditions.uboMaxLights = paths_.uboLights.maxLights();
    conditions.lightMethod = paths_.lightMethod.method;
    conditions.deferred = active_ == PipelineKind::Deferred;
    conditions.runsToEnd = stopBefore.empty();
    conditions.plantAtlas = plants_.atlas != nullptr;
    conditions.atlasColumns = plants_.buffers.atlasColumns();
    conditions.atlasRows = plants_.buffers.atlasRows();
    conditions.cellTexels = plants_.atlas ? float(plants_.atlas->cellSize()) : 1.0f;
    if (plants_.atlas && scene.vegetation.trimmedBillboards) conditions.plantDrawnBounds = &plants_.atlas->drawnBounds();
    conditions.lastGrid = plants_.lastGrid ? &*plants_.lastGrid : nullptr;
    return conditions;
}

void Renderer::prepareVegetation(const SceneSettings& scene) {
    plants_.list.instances.clear();
    plants_.list.directCount = plants_.list.mirroredCount = 0;
    if (frame_.vegetationEnabled && plants_.atlas) {
        const glm::dvec3& camera = frame_.view.pose.position;
        plants_.field.update(scene.terrain, scene.water.level, scene.vegetation,
                                uint32_t(plants_.atlas->variantCount()), camera);
        plants_.lastGrid = terrainGridPlacement(scene, frame_);  // prepareFrame culls by it (mirroredPlantsCulled)
        if (frame_.mirroredPlantsCulled)
            plants_.visibleWater.prepare(scene.terrain, scene.grid, frame_.wedge, scene.viewDistance, frame_.view,
                                  scene.water.level);
        plants_.field.buildDrawList(scene.vegetation, camera, frame_.data.viewProjection, frame_.view.depthMapping,
                                       frame_.reflectionsActive, scene.water.level, plants_.list,
                                       frame_.mirroredPlantsCulled ? &plants_.visibleWater : nullptr);
    } else {
        plants_.field.clearStats();
    }
    plants_.buffers.upload(plants_.list);
}

const Pipeline& Renderer::pipelineOf(PipelineKind kind) const {
    return kind == PipelineKind::Forward ? forward_ : deferred_;
}

FrameRequest FrameRequest::observed(std::function<void(const Pass&)> afterEach) {
    FrameRequest request;
    request.afterEach = std::move(afterEach);
    return request;
}

FrameRequest FrameRequest::buildingPrograms(std::string view) {
    FrameRequest request;
    request.programsOnly = true;
    request.programsView = std::move(view);
    return request;
}

void Renderer::renderFrame(const SceneSettings& scene, const FrameRequest& request) {
    gl::beginFrame();
    if (!request.programsOnly) {
        runFrame(scene, request.stopBefore, request.afterEach);
        return;
    }
    // The marker names this frame in RenderDoc's event list and in apitrace's dump.
    const char* marker = "warm-up: programs built, rasterizer discard on, nothing drawn";
    if (gl::hasDebugGroups())
        glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_MARKER, 0, GL_DEBUG_SEVERITY_NOTIFICATION, -1,
                             marker);
    glEnable(GL_RASTERIZER_DISCARD);
    runFrame(scene, request.stopBefore, request.afterEach);
    if (!request.programsView.empty()) views_.render(request.programsView);
    glDisable(GL_RASTERIZER_DISCARD);
}

void Renderer::runFrame(const SceneSettings& scene, const std::string& stopBefore,
                        const std::function<void(const Pass&)>& afterEach) {
    if (!targets_) throw std::logic_error("Renderer::renderFrame before configure()");
    const Pipeline& pipeline = pipelineOf(active_);
    if (!stopBefore.empty() && !pipeline.hasPass(stopBefore))
        throw std::invalid_argument("the " + std::string(pipelineName(active_)) + " pipeline has no pass '" +
                                    stopBefore + "' (its passes: " + pipeline.passNames() + ")");
    if (!sameGridDensity(scene.grid, geometry_.density())) geometry_ = SceneGeometry(scene.grid);
    paths_.lights = chooseLightsPath(paths_.capabilities.ssbo.available, scene.lights.path, lights_.ssboMissingReason);
    paths_.lightMethod = chooseLightMethod(paths_.capabilities.compute.available, scene.lights.method,
                                          paths_.capabilities.compute.reason, paths_.lights.path);
    frame_ = prepareFrame(scene, targets_->width(), targets_->height(), frameConditions(scene, stopBefore));
    prepareVegetation(scene);
    uploadLights();
    glBindBuffer(GL_UNIFORM_BUFFER, frameUniforms_.name());
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(FrameData), &frame_.data);
    glBindBufferRange(GL_UNIFORM_BUFFER, kFrameBlockBinding, frameUniforms_.name(), 0, sizeof(FrameData));
    if (!stopBefore.empty()) {
        // Final is not reached: show black rather than whatever an earlier frame left there.
        const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        glBindFramebuffer(GL_FRAMEBUFFER, targets_->framebuffer({Target::Final}));
        glClearBufferfv(GL_COLOR, 0, black);
    }
    PassContext passContext = context();
    if (frame_.reflectionsActive && frame_.reflectionDivisor > 1) {
        prepareReducedReflection();
        passContext.frameBlock = frameUniforms_.name();
        passContext.reflectionFrameRange = reducedReflectionFrameRange();
    }
    left_.stepsRan.clear();
    std::vector<Target> beyondFrame;
    left_.graph = requestGraph(stopBefore, beyondFrame);
    // The graph's plan of the frame's targets: those it does not use are given back (a forward
    // frame holds no G-buffer), those whose lifetimes do not overlap may share a texture.
    const FrameGraph& graph = left_.graph;
    // The reduced reflection's targets are among them, at their scale.
    left_.lifetimes = oasis::targetLifetimes(graph, frame_, beyondFrame);
    targets_->plan(left_.lifetimes);
    FrameClipControl clipControl(targets_->depth());
    pipeline.run(passContext, graph, [&](const Pass& pass) {
        if (!pass.sceneStep().empty()) left_.stepsRan.push_back(pass.sceneStep());
        if (afterEach) afterEach(pass);
    });
    left_.gbufferHolds.reset();
    // The water awaits Radiance where the graph keeps the composite onto it (a view of Radiance
    // asked); a whole frame's, wherever the fused composite ran (any view may be drawn after it).
    const bool viewsInGraph = std::any_of(graph.steps.begin(), graph.steps.end(),
                                          [](const GraphStep& step) { return step.afterFrame; });
    left_.radianceAwaitsWater =
        lonePasses_.waterComposite.active(frame_) &&
        graph.runs(viewsInGraph ? lonePasses_.waterComposite.name() : std::string("WaterCompositePass"));
    left_.stoppedBefore = stopBefore;
    left_.stoppedGBufferCurrent = !stopBefore.empty() && pipeline.writes(frame_, Target::Albedo);
}

FrameGraph Renderer::requestGraph(const std::string& stopBefore, std::vector<Target>& beyondFrame) const {
    auto targetsIn = [&](const std::vector<Resource>& resources) {
        for (const Resource& resource : resources)
            if (const Target* target = std::get_if<Target>(&resource)) beyondFrame.push_back(*target);
    };
    std::vector<GraphStep> steps;
    for (const auto& pass : pipelineOf(active_).passes()) steps.push_back(graphStep(*pass, frame_));
    if (views_.sink_.empty() || !stopBefore.empty()) {
        targetsIn(frameOutputs());
        targetsIn(everyResource());  // the fill of a whole frame's views may write any target
        // A stopped frame is the whole frame's graph cut before the pass: the passes before it run
        // as they would in the whole frame, and its targets are planned as the whole frame's.
        FrameGraph graph = buildFrameGraph(std::move(steps), frame_, frameOutputs(), frameInputs());
        if (!stopBefore.empty()) cutAt(graph, stopBefore);
        return graph;
    }
    // After the frame, from the sink: the water laid onto Radiance where the tone map was fused and
    // a view (or the sink's other reader, readTarget) reads Radiance; that reader's reads, of the
    // frame as it leaves it; the views' fill for a view of the frame's surfaces; the views.
    const std::vector<const ViewPass*> shown = views_.sinkPasses();
    auto anyView = [&](bool (ViewPass::*reads)() const) {
        return std::any_of(shown.begin(), shown.end(), [&](const ViewPass* pass) { return (pass->*reads)(); });
    };
    const std::vector<Resource>& readAfter = views_.sinkReads_;
    const bool radiance = anyView(&ViewPass::readsRadiance) ||
                          std::find(readAfter.begin(), readAfter.end(), Resource(Target::Radiance)) != readAfter.end();
    if (radiance && frame_.toneMapFused) steps.push_back(graphStep(lonePasses_.waterComposite, frame_, true));
    steps.back().readAfter = readAfter;
    if (anyView(&ViewPass::readsSurfaces))
        for (const Pass* pass : viewFill_.passes(views_.waterScene_, frame_)) steps.push_back(graphStep(*pass, frame_, true));
    for (const ViewPass* pass : shown) steps.push_back(graphStep(*pass, frame_, true));
    FrameGraph graph = buildFrameGraph(std::move(steps), frame_, {Screen::Display}, frameInputs());
    // What the views' passes touch lives past the frame: they run as each view is drawn.
    for (const GraphStep& step : graph.steps) {
        if (!step.afterFrame) continue;
        targetsIn(step.writes);
        if (step.runs) targetsIn(step.reads);
    }
    targetsIn(readAfter);
    return graph;
}

void Renderer::prepareReducedReflection() {
    const int divisor = frame_.reflectionDivisor;
    const int width = targets_->width(divisor), height = targets_->height(divisor);
    // The frame's data for the smaller targets: their pixels (rays through pixel centres, the
    // billboards' mip levels) and how the frame's water rectangle maps onto them (widened by a
    // pixel for the upsample's taps).
    FrameData data = frame_.data;
    const float scaleX = float(width) / float(targets_->width()), scaleY = float(height) / float(targets_->height());
    data.screen = glm::vec4(float(width), float(height), 1.0f / float(width), 1.0f / float(height));
    data.vegetationAtlas.w *= scaleY;
    data.targetScale = glm::vec4(scaleX, scaleY, 1.0f, 0.0f);
    glBindBuffer(GL_UNIFORM_BUFFER, frameUniforms_.name());
    glBufferSubData(GL_UNIFORM_BUFFER, reducedReflectionFrameRange(), sizeof(FrameData), &data);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

void Renderer::forgetGBuffer() {
    left_.gbufferHolds.reset();
    left_.stoppedGBufferCurrent = false;
}

void Renderer::ensureRadiance() {
    if (!left_.radianceAwaitsWater) return;
    left_.radianceAwaitsWater = false;
    // The graph's composite onto Radiance; the stencil and depth are still the frame's
    // (ensureGBuffer calls this before a view fill redraws them).
    PassContext passContext = context();
    FrameClipControl clipControl(targets_->depth());
    runValidated(lonePasses_.waterComposite, passContext);
}

void Renderer::ensureGBuffer() {
    ensureRadiance();
    if (!left_.stoppedBefore.empty()) {
        fillStoppedFrame();
        return;
    }
    if (left_.gbufferHolds == views_.waterScene_) return;
    PassContext passContext = context();
    FrameClipControl clipControl(targets_->depth());
    views_.scene_ = viewFill_.run(passContext, views_.waterScene_);
    left_.gbufferHolds = views_.waterScene_;
}

void Renderer::fillSurfacesWithTheirDepth() {
    // After a whole frame the water composite has written the water's depth over the mirrored
    // scene the G-buffer holds there. A layout that rebuilds positions from depth reads them from
    // those surfaces refilled with their own depth: the mirrored view fill, what the frame left.
    if (targets_->layout().positionFromDepth() && left_.stoppedBefore.empty() && !left_.gbufferHolds) {
        WaterScene asked = views_.waterScene_;
        views_.waterScene_ = WaterScene::Mirrored;
        ensureGBuffer();
        views_.waterScene_ = asked;
    }
}

void Renderer::fillExactSurfaces(const FrameTargets& exact, WaterScene scene) {
    ensureRadiance();  // the frame's Radiance complete, as ensureGBuffer leaves it
    // The frame, but the passes declare (and bind) the targets of `exact`'s layout.
    FrameSetup frame = frame_;
    frame.positionFromDepth = exact.layout().positionFromDepth();
    PassContext passContext = contextOver(exact, frame);
    FrameClipControl clipControl(exact.depth());
    viewFill_.run(passContext, scene);
}

void Renderer::fillStoppedFrame() {
    views_.scene_ = ViewScene{std::nullopt,
                           active_ == PipelineKind::Forward
                               ? "the direct scene's steps that ran before " + left_.stoppedBefore
                               : "what the frame left there before " + left_.stoppedBefore,
                           "the frame was stopped early (--stop-before): its targets are shown as they were"};
    if (left_.stoppedGBufferCurrent) return;
    PassContext passContext = context();
    // Forward draws no G-buffer: fill it for the view with the deferred passes of the direct scene
    // that do not shade, each only if the forward pass of the same scene step ran this frame, so a
    // frame stopped early keeps its depth and stencil. Radiance and Final stay the forward frame's.
    auto ranInForward = [&](const Pass& pass) {
        return !pass.sceneStep().empty() &&
               std::find(left_.stepsRan.begin(), left_.stepsRan.end(), pass.sceneStep()) != left_.stepsRan.end();
    };
    bool filled = false;
    FrameClipControl clipControl(targets_->depth());
    // The depth copy has no forward counterpart: it follows whatever the fill drew, where the
    // deferred frame's graph keeps it.
    FrameGraph deferredGraph = deferred_.graph(frame_);
    for (const auto& pass : viewFill_.stoppedFrameFill()) {
        bool copiesDepth = pass->writes(frame_, Target::SceneDepth);
        if (copiesDepth ? filled && deferredGraph.runs(pass->name()) : ranInForward(*pass)) {
            runValidated(*pass, passContext);
            filled = true;
        }
    }
    left_.stoppedGBufferCurrent = true;
}

void Renderer::renderFloor() {
    gl::beginFrame();
    PassContext passContext = context();
    lonePasses_.floor.run(passContext);
    forgetGBuffer();
}

void Renderer::present(int windowWidth, int windowHeight) {
    PassContext passContext = context();
    lonePasses_.present.run(passContext, windowWidth, windowHeight);
}

}  // namespace oasis
