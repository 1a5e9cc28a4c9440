// The frame's validation (frame/frame_graph.h): a pass that draws into a target it does not
// declare fails it, so does one that declares a write it never binds, one that binds its declared
// outputs passes, and the real frames of both
// pipelines pass it in the settings that change their declarations.
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
    std::vector<Access> accesses(const FrameSetup&) const override { return {{Target::Radiance, Use::Write}}; }

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
    std::vector<Access> accesses(const FrameSetup&) const override {
        return {{Target::Radiance, Use::Write}, {Target::Final, Use::Write}};
    }

protected:
    void execute(PassContext& context) override {
        bindFramebufferOf(context.targets, {{Target::Radiance, Use::Write}});
        const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        glClearBufferfv(GL_COLOR, 0, black);
    }
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

}  // namespace
}  // namespace oasis::gputest
