// The frame's validation (frame/frame_graph.h, frame/input_audit.h): a pass that draws into a
// target it does not declare fails it, so does one that declares a write it never binds, or one that
// samples a target or reads a buffer it does not declare; one that binds its declared outputs
// passes, a pass finds what it declares it samples bound, and the real frames of both pipelines
// pass it in the settings that change their declarations.
#include "gpu_test.h"

#include <stdexcept>

#include "frame/frame_graph.h"
#include "frame/pipeline.h"

namespace oasis::gputest {
namespace {

// Declares that it writes Radiance; `honest` draws there, otherwise it clears Final.
class ClearsOneTarget : public Pass {
public:
    explicit ClearsOneTarget(bool honest) : honest_(honest) {}
    std::string name() const override { return honest_ ? "DeclaredPass" : "MisdeclaredPass"; }
    std::vector<Access> declaredAccesses(const FrameSetup&) const override { return {{Target::Radiance, Use::Write}}; }

protected:
    void execute(PassContext& context) override {
        if (honest_) bindDeclaredOutputs(context);
        else bindFramebufferOf(context.targets, {{Target::Final, Use::Write}});
        const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        glClearBufferfv(GL_COLOR, 0, black);
    }

private:
    bool honest_;
};

// Declares that it writes Radiance and Final, and binds (and clears) Radiance alone.
class DeclaresAWriteItNeverMakes : public Pass {
public:
    std::string name() const override { return "OverdeclaredPass"; }
    std::vector<Access> declaredAccesses(const FrameSetup&) const override {
        return {{Target::Radiance, Use::Write}, {Target::Final, Use::Write}};
    }

protected:
    void execute(PassContext& context) override {
        bindFramebufferOf(context.targets, {{Target::Radiance, Use::Write}});
        const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        glClearBufferfv(GL_COLOR, 0, black);
    }
};

// Draws into Final while it reads a target (Radiance, the reduced Reflection) or the light list (a
// buffer), bound by hand where the table reads it unless `declares`: then the pass declares the
// read and binds nothing.
// `bound` is what the pass found on the input's unit or binding.
class ReadsAnInput : public Pass {
public:
    ReadsAnInput(Resource input, bool declares) : input_(input), declares_(declares) {}
    std::string name() const override {
        return std::string(declares_ ? "Declared" : "Undeclared") +
               (std::holds_alternative<Buffer>(input_) ? "BufferPass" : "SamplePass");
    }
    std::vector<Access> declaredAccesses(const FrameSetup&) const override {
        std::vector<Access> used = {{Target::Final, Use::Write}};
        if (declares_) used.push_back({input_, Use::Sample});
        return used;
    }
    GLint bound = 0;
    gl::Buffer lights;

protected:
    void execute(PassContext& context) override {
        bindDeclaredOutputs(context);
        Target sampled;
        int divisor;
        bool target = targetOf(input_, sampled, divisor);
        int unit = 0;
        for (const InputBinding& row : kInputBindings)
            if (row.resource == input_) unit = row.binding;
        if (!declares_ && target) {
            glActiveTexture(GLenum(GL_TEXTURE0 + unit));
            glBindTexture(GL_TEXTURE_2D, context.targets.texture(sampled, divisor));
        }
        if (!declares_ && !target) {
            lights = gl::createBuffer("test: the light count");
            glBindBuffer(GL_UNIFORM_BUFFER, lights.name());
            glBufferData(GL_UNIFORM_BUFFER, 16, nullptr, GL_DYNAMIC_DRAW);
            glBindBufferBase(GL_UNIFORM_BUFFER, kLightCountBlockBinding, lights.name());
        }
        if (target) {
            glActiveTexture(GLenum(GL_TEXTURE0 + unit));
            glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
            glActiveTexture(GL_TEXTURE0);
        } else {
            glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, kLightCountBlockBinding, &bound);
        }
        const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        glClearBufferfv(GL_COLOR, 0, black);
    }

private:
    Resource input_;
    bool declares_;
};

// Switches validation on for the scope, as debug builds have it.
struct ValidatedFrames {
    bool was = frameValidation();
    ValidatedFrames() { setFrameValidation(true); }
    ~ValidatedFrames() { setFrameValidation(was); }
};

// A small compact frame's targets and context for running one pass validated; the error it
// throws must name `expected`.
struct OnePassFrame {
    explicit OnePassFrame(ShaderLibrary& shaders) : context{targets, shaders, geometry, frame, vegetation} {}
    ~OnePassFrame() { glBindFramebuffer(GL_FRAMEBUFFER, 0); }
    void expectRejected(Pass& pass, const std::string& expected, const char* why) {
        try {
            runValidated(pass, context);
            ADD_FAILURE() << why;
        } catch (const std::logic_error& error) {
            EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
        }
    }
    FrameTargets targets{layoutNamed("compact"), standardDepthConvention(), 32, 18};
    SceneGeometry geometry{SceneSettings{}.grid};
    VegetationBuffers vegetation;
    FrameSetup frame;
    PassContext context;
};

TEST_F(GpuTest, APassDrawingOutsideItsDeclarationFailsValidation) {
    ValidatedFrames validated;
    OnePassFrame one(*shaders_);
    ClearsOneTarget declared(true), misdeclared(false);
    EXPECT_NO_THROW(runValidated(declared, one.context));
    one.expectRejected(misdeclared, "MisdeclaredPass draws into final",
                       "a pass that cleared Final while declaring Radiance passed validation");
}

TEST_F(GpuTest, APassDeclaringAWriteItNeverMakesFailsValidation) {
    ValidatedFrames validated;
    OnePassFrame one(*shaders_);
    DeclaresAWriteItNeverMakes overdeclared;
    one.expectRejected(overdeclared, "OverdeclaredPass declares it writes final but never binds it",
                       "a pass that declared Final and never bound it passed validation");
}

// A pass reading `input` passes validation where it declares it, and fails it naming `expected`
// where it does not.
void expectReadAudited(ShaderLibrary& shaders, Resource input, const std::string& expected, const char* why) {
    ValidatedFrames validated;
    OnePassFrame one(shaders);
    ReadsAnInput declared(input, true), undeclared(input, false);
    EXPECT_NO_THROW(runValidated(declared, one.context));
    one.expectRejected(undeclared, expected, why);
}

TEST_F(GpuTest, APassSamplingATargetItDoesNotDeclareFailsValidation) {
    expectReadAudited(*shaders_, Target::Radiance,
                      "UndeclaredSamplePass samples radiance (texture unit 9), which it does not declare",
                      "a pass that sampled Radiance without declaring it passed validation");
}

// The reduced reflection's Reflection is a target at its scale, audited as the frame's are: the
// upsample must declare it (it does, and so its lifetime reaches it).
TEST_F(GpuTest, APassSamplingAReducedTargetItDoesNotDeclareFailsValidation) {
    for (int divisor : {2, 4})
        expectReadAudited(*shaders_, ScaledTarget{Target::Reflection, divisor},
                          "UndeclaredSamplePass samples reflection at 1/" + std::to_string(divisor) +
                              " (texture unit 6), which it does not declare",
                          "a pass that sampled the reduced Reflection without declaring it passed validation");
}

// The reduced reflection's frames, validated: the upsample's read of the reduced Reflection and
// the mirrored passes' draws at its scale are all declared.
TEST_F(GpuTest, TheReducedReflectionsFramesPassValidation) {
    ValidatedFrames validated;
    SceneSettings scene = defaultPose().scene;
    Renderer renderer(*shaders_, scene);
    renderer.configure(64, 36, layoutNamed("compact"));
    for (int divisor : {2, 4})
        for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
            scene.water.reflectionDivisor = divisor;
            renderer.setPipeline(kind);
            EXPECT_NO_THROW(renderer.renderFrame(scene)) << pipelineName(kind) << " at 1/" << divisor;
            EXPECT_TRUE(renderer.lastFrame().setup.reflectionsActive);
        }
}

TEST_F(GpuTest, APassReadingABufferItDoesNotDeclareFailsValidation) {
    expectReadAudited(*shaders_, Buffer::LightList,
                      "UndeclaredBufferPass reads LightList (uniform block binding 1), which it does not declare",
                      "a pass that read the light list without declaring it passed validation");
}

// The pipeline binds what a pass declares it samples before it executes (bindDeclaredInputs), with
// validation off as on: the pass binds nothing itself.
TEST_F(GpuTest, APassFindsWhatItDeclaresItSamplesBoundOnItsUnit) {
    OnePassFrame one(*shaders_);
    glActiveTexture(GL_TEXTURE0 + kUnitRadiance);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    ReadsAnInput declared(Target::Radiance, true);
    declared.run(one.context);
    EXPECT_NE(declared.bound, 0);
    EXPECT_EQ(GLuint(declared.bound), one.targets.texture(Target::Radiance));
}

TEST_F(GpuTest, TheFramesOfBothPipelinesPassValidation) {
    ValidatedFrames validated;
    for (const char* layout : {"compact", "full"}) {
        for (LightMethod method : {LightMethod::Volumes, LightMethod::Tiled}) {
            for (bool inPlace : {true, false}) {
                SceneSettings scene = defaultPose().scene;
                scene.hour = 21.0;
                scene.lights.count = 4;
                scene.lights.method = method;
                scene.work.depthReadInPlace = inPlace;
                Renderer renderer(*shaders_, scene);
                renderer.configure(64, 36, layoutNamed(layout));
                for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
                    renderer.setPipeline(kind);
                    EXPECT_NO_THROW(renderer.renderFrame(scene)) << layout << " " << pipelineName(kind);
                    EXPECT_NO_THROW(renderer.views().render("albedo")) << layout << " " << pipelineName(kind);
                }
            }
        }
    }
}

// The views' passes after the frame (issue 43 item 3) are validated like the frame's: each view
// drawn after a frame built for it, in both pipelines and both tone maps, samples only what its
// pass declares (the composite onto Radiance, the fill and DebugViewPass.<view>), and the graph has
// a writer before every read of theirs.
TEST_F(GpuTest, EveryViewsPassesAfterItsFramePassValidation) {
    ValidatedFrames validated;
    std::vector<std::string> views = {kOverviewName};
    for (const DebugView& view : debugViews()) views.push_back(view.name);
    for (bool fused : {true, false}) {
        SceneSettings scene = defaultPose().scene;
        scene.work.fuseToneMap = fused;
        for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
            for (const std::string& view : views) {
                Renderer renderer(*shaders_, scene);
                renderer.configure(64, 36, layoutNamed("compact"));
                renderer.setPipeline(kind);
                renderer.views().setSink({view});
                EXPECT_NO_THROW(renderer.renderFrame(scene)) << view << " " << pipelineName(kind);
                EXPECT_TRUE(renderer.lastFrame().graph().runs("DebugViewPass." + view)) << view;
                EXPECT_NO_THROW(renderer.views().render(view)) << view << " " << pipelineName(kind);
            }
        }
    }
}

}  // namespace
}  // namespace oasis::gputest
