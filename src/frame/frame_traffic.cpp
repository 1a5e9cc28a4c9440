// Counting a frame's traffic: per-pass queries, and the clears seen by swapping libepoxy's
// dispatch pointers for glClearBuffer* (and glBegin/EndQuery, so the frame's own occlusion query
// never meets ours on the binding they share) for the counted frame only.
#include "frame/frame_traffic.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <stdexcept>

#include "frame/renderer.h"
#include "passes/floor_pass.h"
#include "render/depth_convention.h"

namespace oasis {
namespace {

bool occlusionTarget(GLenum target) {
    return target == GL_SAMPLES_PASSED || target == GL_ANY_SAMPLES_PASSED ||
           target == GL_ANY_SAMPLES_PASSED_CONSERVATIVE;
}

bool pipelineStatistics() {
    return epoxy_is_desktop_gl() &&
           (epoxy_gl_version() >= 46 || epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query"));
}

// The bytes per pixel of the frame's targets among `declared` (the buffers passes hand each other
// are not per pixel: left out, docs/traffic.md).
double declaredBytes(const FrameTargets& targets, const std::vector<Resource>& declared) {
    double bytes = 0.0;
    for (const Resource& resource : declared) {
        Target target;
        int divisor;  // per fragment: a target at a reduced scale has its bytes per texel too
        if (targetOf(resource, target, divisor))
            bytes += targetFormat(targets.layout(), targets.depth(), target).bytesPerPixel;
    }
    return bytes;
}

// The counter of the frame being measured: one at a time, reached from the hooks.
class Counter;
Counter* active = nullptr;

decltype(epoxy_glClearBufferfv) realClearBufferfv = nullptr;
decltype(epoxy_glClearBufferfi) realClearBufferfi = nullptr;
decltype(epoxy_glBeginQuery) realBeginQuery = nullptr;
decltype(epoxy_glEndQuery) realEndQuery = nullptr;

class Counter {
public:
    explicit Counter(const FrameTargets& targets) : targets_(targets), statistics_(pipelineStatistics()) {
        glGenQueries(1, &samples_);
        glGenQueries(1, &invocations_);
        resolveDispatch();
        realClearBufferfv = epoxy_glClearBufferfv;
        realClearBufferfi = epoxy_glClearBufferfi;
        realBeginQuery = epoxy_glBeginQuery;
        realEndQuery = epoxy_glEndQuery;
        epoxy_glClearBufferfv = &clearBufferfv;
        epoxy_glClearBufferfi = &clearBufferfi;
        epoxy_glBeginQuery = &beginQuery;
        epoxy_glEndQuery = &endQuery;
        active = this;
    }
    ~Counter() {
        epoxy_glClearBufferfv = realClearBufferfv;
        epoxy_glClearBufferfi = realClearBufferfi;
        epoxy_glBeginQuery = realBeginQuery;
        epoxy_glEndQuery = realEndQuery;
        active = nullptr;
        glDeleteQueries(1, &samples_);
        glDeleteQueries(1, &invocations_);
    }
    Counter(const Counter&) = delete;
    Counter& operator=(const Counter&) = delete;

    bool statistics() const { return statistics_; }
    void begin() {
        realBeginQuery(GL_SAMPLES_PASSED, samples_);
        if (statistics_) realBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, invocations_);
    }
    // Ends the open queries and adds what they counted to the pass being counted.
    void end(bool samplesOpen = true) {
        if (samplesOpen) realEndQuery(GL_SAMPLES_PASSED);
        if (statistics_) realEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
        GLuint64 samples = 0, invocations = 0;
        if (samplesOpen) glGetQueryObjectui64v(samples_, GL_QUERY_RESULT, &samples);
        if (statistics_) glGetQueryObjectui64v(invocations_, GL_QUERY_RESULT, &invocations);
        if (!statistics_) invocations = samples;
        if (samplesOpen) {
            current_.samples += samples;
        } else {
            current_.samples += invocations;  // the most it can have been
            current_.samplesUncounted += invocations;
        }
        current_.invocations += invocations;
    }
    // The counts since the last take, for the pass that just ran.
    PassTraffic take(const std::string& name) {
        PassTraffic counted = current_;
        counted.name = name;
        current_ = {};
        return counted;
    }

private:
    // libepoxy's pointers start at a stub that, on first use, stores the real function in the
    // pointer and calls through it: a hook installed over a stub would then call itself. A call of
    // each that changes nothing resolves them first.
    void resolveDispatch() {
        glBeginQuery(GL_SAMPLES_PASSED, samples_);
        glEndQuery(GL_SAMPLES_PASSED);
        GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
        GLint box[4];
        glGetIntegerv(GL_SCISSOR_BOX, box);
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, 0, 0);  // an empty box: the clears below write nothing
        const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        glClearBufferfv(GL_COLOR, 0, zero);
        glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
        glScissor(box[0], box[1], box[2], box[3]);
        if (!scissor) glDisable(GL_SCISSOR_TEST);
    }

    // Bytes one texel of an attachment of the draw framebuffer holds of `parts` (colour, depth,
    // stencil): a frame target's from the layout table, another's (shadow maps, the reduced
    // reflection's targets) from the driver's component sizes.
    double texelBytes(GLenum attachment, bool depth, bool stencil, GLint& texture, GLint& level, bool& frameTarget) const {
        frameTarget = false;
        GLint type = GL_NONE;
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
        if (type != GL_TEXTURE) return 0.0;
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &texture);
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &level);
        bool whole = attachment != GL_DEPTH_STENCIL_ATTACHMENT || (depth && stencil);
        for (int t = 0; t < int(Target::Count) && whole; ++t)
            if (targets_.texture(Target(t)) == GLuint(texture)) {
                frameTarget = true;
                return targetFormat(targets_.layout(), targets_.depth(), Target(t)).bytesPerPixel;
            }
        int bits = 0;
        auto size = [&](GLenum pname) {
            GLint value = 0;
            glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment, pname, &value);
            bits += value;
        };
        if (attachment >= GL_COLOR_ATTACHMENT0 && attachment <= GL_COLOR_ATTACHMENT15) {
            for (GLenum pname : {GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE, GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE,
                                 GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE, GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE})
                size(pname);
        } else {
            if (depth) size(GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE);
            if (stencil) size(GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE);
        }
        return bits / 8.0;
    }

    // The texels a clear writes: the attachment's level, inside the scissor box where it is on.
    double clearedTexels(GLint texture, GLint level) const {
        GLint width = targets_.width(), height = targets_.height();
        if (texture && (epoxy_gl_version() >= 45 || epoxy_has_gl_extension("GL_ARB_direct_state_access"))) {
            glGetTextureLevelParameteriv(GLuint(texture), level, GL_TEXTURE_WIDTH, &width);
            glGetTextureLevelParameteriv(GLuint(texture), level, GL_TEXTURE_HEIGHT, &height);
        }
        if (glIsEnabled(GL_SCISSOR_TEST)) {
            GLint box[4];
            glGetIntegerv(GL_SCISSOR_BOX, box);
            width = std::max(0, std::min(width, box[0] + box[2]) - std::max(0, box[0]));
            height = std::max(0, std::min(height, box[1] + box[3]) - std::max(0, box[1]));
        }
        return double(width) * double(height);
    }

    void countClear(GLenum buffer, GLint drawBuffer) {
        GLint framebuffer = 0;
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
        if (framebuffer == 0) return;  // the frame never clears the default framebuffer
        GLenum attachment = GL_NONE;
        if (buffer == GL_COLOR) {
            GLint drawn = GL_NONE;
            glGetIntegerv(GL_DRAW_BUFFER0 + drawBuffer, &drawn);
            attachment = GLenum(drawn);
        } else {
            attachment = buffer == GL_DEPTH ? GL_DEPTH_ATTACHMENT
                         : buffer == GL_STENCIL ? GL_STENCIL_ATTACHMENT : GL_DEPTH_STENCIL_ATTACHMENT;
        }
        if (attachment == GL_NONE) return;
        GLint texture = 0, level = 0;
        bool frameTarget = false;
        double bytes = texelBytes(attachment, buffer != GL_STENCIL, buffer == GL_STENCIL || buffer == GL_DEPTH_STENCIL,
                                  texture, level, frameTarget);
        uint64_t cleared = uint64_t(bytes * clearedTexels(texture, level) + 0.5);
        current_.clearedBytes += cleared;
        if (!frameTarget) current_.clearedElsewhere += cleared;
    }

    static void EPOXY_CALLSPEC clearBufferfv(GLenum buffer, GLint drawBuffer, const GLfloat* value) {
        if (active) active->countClear(buffer, drawBuffer);
        realClearBufferfv(buffer, drawBuffer, value);
    }
    static void EPOXY_CALLSPEC clearBufferfi(GLenum buffer, GLint drawBuffer, GLfloat depth, GLint stencil) {
        if (active) active->countClear(buffer, drawBuffer);
        realClearBufferfi(buffer, drawBuffer, depth, stencil);
    }
    // The frame's own occlusion query (the water mask's) takes the binding ours holds: ours ends
    // there, the invocations go on being counted, and ours resumes when the frame's ends.
    static void EPOXY_CALLSPEC beginQuery(GLenum target, GLuint id) {
        if (active && occlusionTarget(target)) {
            active->end();
            realBeginQuery(target, id);
            if (active->statistics_) realBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, active->invocations_);
            return;
        }
        realBeginQuery(target, id);
    }
    static void EPOXY_CALLSPEC endQuery(GLenum target) {
        realEndQuery(target);
        if (active && occlusionTarget(target)) {
            active->end(false);
            active->begin();
        }
    }

    const FrameTargets& targets_;
    bool statistics_;
    GLuint samples_ = 0, invocations_ = 0;
    PassTraffic current_;
};

void addDeclaredBytes(PassTraffic& pass, const FrameTargets& targets, const FrameSetup& frame, const Pass& declared) {
    pass.bytesWritten = double(pass.samples) * declaredBytes(targets, declared.writes(frame)) + double(pass.clearedBytes);
    pass.bytesRead = double(pass.invocations) * declaredBytes(targets, declared.reads(frame));
}

void merge(std::vector<PassTraffic>& passes, const PassTraffic& pass) {
    for (PassTraffic& earlier : passes)
        if (earlier.name == pass.name) {
            earlier.samples += pass.samples;
            earlier.invocations += pass.invocations;
            earlier.samplesUncounted += pass.samplesUncounted;
            earlier.clearedBytes += pass.clearedBytes;
            earlier.clearedElsewhere += pass.clearedElsewhere;
            earlier.bytesWritten += pass.bytesWritten;
            earlier.bytesRead += pass.bytesRead;
            return;
        }
    passes.push_back(pass);
}

// The floor's counts: two full-screen draws of equal size, the write (its declared targets but
// Final) and the read (the G-buffer into Final), each half of them.
void countFloor(PassTraffic counted, const FrameTargets& targets, const FrameSetup& frame, FrameTraffic& traffic) {
    FloorPass floor;
    std::vector<Resource> gbufferWrites, finalWrites{Target::Final};
    for (const Resource& resource : floor.writes(frame))
        if (resource != Resource(Target::Final)) gbufferWrites.push_back(resource);
    const double half = 0.5;
    counted.bytesWritten = half * double(counted.samples) *
                               (declaredBytes(targets, gbufferWrites) + declaredBytes(targets, finalWrites)) +
                           double(counted.clearedBytes);
    counted.bytesRead = half * double(counted.invocations) * declaredBytes(targets, floor.reads(frame));
    traffic.passes.push_back(counted);
}

}  // namespace

double FrameTraffic::bytesWritten() const {
    double sum = 0.0;
    for (const PassTraffic& pass : passes) sum += pass.bytesWritten;
    return sum;
}

double FrameTraffic::bytesRead() const {
    double sum = 0.0;
    for (const PassTraffic& pass : passes) sum += pass.bytesRead;
    return sum;
}

double FrameTraffic::clearedBytes() const {
    double sum = 0.0;
    for (const PassTraffic& pass : passes) sum += double(pass.clearedBytes);
    return sum;
}

double FrameTraffic::clearedElsewhereBytes() const {
    double sum = 0.0;
    for (const PassTraffic& pass : passes) sum += double(pass.clearedElsewhere);
    return sum;
}

const PassTraffic* FrameTraffic::find(const std::string& name) const {
    for (const PassTraffic& pass : passes)
        if (pass.name == name) return &pass;
    return nullptr;
}

bool trafficCountable(std::string* whyNot) {
    if (epoxy_is_desktop_gl()) return true;
    if (whyNot) *whyNot = "OpenGL ES has no GL_SAMPLES_PASSED (only boolean occlusion queries)";
    return false;
}

std::string describeInvocationCount(const FrameTraffic& traffic) {
    return traffic.invocationsCounted
               ? "fragment invocations from GL_ARB_pipeline_statistics_query"
               : "no GL_ARB_pipeline_statistics_query: fragment invocations stand in as samples passed";
}

// Counts what `draw` does on the renderer's targets; `draw` ends the counter's last queries.
FrameTraffic countedDraw(Renderer& renderer, const std::function<void(Counter&, FrameTraffic&)>& draw) {
    FrameTraffic traffic;
    const FrameTargets& targets = renderer.targets();
    traffic.width = targets.width();
    traffic.height = targets.height();
    Counter counter(targets);
    traffic.invocationsCounted = counter.statistics();
    counter.begin();
    draw(counter, traffic);
    return traffic;
}

FrameTraffic measureFrameTraffic(Renderer& renderer, const SceneSettings& scene) {
    if (!trafficCountable()) return {};
    renderer.renderFrame(scene);  // programs built, buffers sized: the counted frame only draws
    return countedDraw(renderer, [&](Counter& counter, FrameTraffic& traffic) {
        renderer.renderFrame(scene, FrameRequest::observed([&](const Pass& pass) {
            counter.end();
            PassTraffic counted = counter.take(pass.name());
            addDeclaredBytes(counted, renderer.targets(), renderer.lastFrame().setup, pass);
            merge(traffic.passes, counted);
            counter.begin();
        }));
        counter.end();
        counter.take("");  // the frame's tail after its last pass: not a pass
    });
}

FrameTraffic measureFloorTraffic(Renderer& renderer) {
    if (!trafficCountable()) return {};
    renderer.renderFloor();
    return countedDraw(renderer, [&](Counter& counter, FrameTraffic& traffic) {
        renderer.renderFloor();
        counter.end();
        countFloor(counter.take(FloorPass().name()), renderer.targets(), renderer.lastFrame().setup, traffic);
    });
}

}  // namespace oasis
