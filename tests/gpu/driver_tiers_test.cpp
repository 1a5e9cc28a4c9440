// What every driver set-up must do (ctest runs this binary on llvmpipe, zink, softpipe and
// llvmpipe without SSBOs/compute): both pipelines and every debug view at the set-up's frame size
// ($OASIS_GPU_TIER_SIZE, default 320x180; softpipe runs at 96x54), forward and deferred agreeing,
// and each fallback that can be forced in this process drawing the unforced image bit for bit.
#include <cstdlib>

#include "cli/options.h"
#include "commands/session.h"
#include "debug/debug_views.h"
#include "frame/frame_readback.h"
#include "gpu_test.h"

namespace oasis::gputest {
namespace {

class DriverTiers : public GpuTest {};

void tierSize(int& width, int& height) {
    width = 320;
    height = 180;
    const char* size = std::getenv("OASIS_GPU_TIER_SIZE");
    if (size && *size && !parseSize(size, width, height)) ADD_FAILURE() << "bad OASIS_GPU_TIER_SIZE " << size;
}

// The session a command would make (capabilities, paths, plant atlas) with these fallbacks forced.
std::unique_ptr<RenderSession> sessionWith(const gl::ForcedFallbacks& forced) {
    Options options;
    tierSize(options.scene.width, options.scene.height);
    options.scene.force = forced;
    return std::make_unique<RenderSession>(options);
}

struct Frames {
    Image forward, deferred, overview;
};
Frames renderFrames(RenderSession& session) {
    Frames frames;
    Renderer& renderer = *session.renderer;
    frames.forward = renderFinal(renderer, session.scene, PipelineKind::Forward);
    frames.deferred = renderFinal(renderer, session.scene, PipelineKind::Deferred);
    renderer.views().render(kOverviewName);  // every view, the stencil and the plant atlas included
    frames.overview = readDisplay(renderer);
    return frames;
}

TEST_F(DriverTiers, BothPipelinesEveryViewAndAgreementAtTheSetUpsSize) {
    auto session = sessionWith({});
    Renderer& renderer = *session->renderer;
    std::printf("[tier] %s, %dx%d, stencil view %s, plants %s\n", gpuState().info.summary().c_str(),
                renderer.targets().width(), renderer.targets().height(),
                stencilViewPathName(renderer.views().stencilPath()), plantInterpretationName(session->plantAtlas->path()));
    Frames frames = renderFrames(*session);
    EXPECT_TRUE(hasContent(frames.forward)) << "forward";
    EXPECT_TRUE(hasContent(frames.deferred)) << "deferred";
    // The agreement suite's threshold for the standard layout (tests/gpu/agreement_test.cpp).
    ImageDifference difference = compareImages(frames.forward, frames.deferred);
    std::printf("[tier] forward vs deferred PSNR %.2f dB, max abs %d\n", difference.psnrDb, difference.maxAbs);
    EXPECT_GE(difference.psnrDb, 45.0) << "forward and deferred disagree on this driver";
    for (const DebugView& view : debugViews()) {
        renderer.views().render(view.name);
        Image image = readDisplay(renderer);
        EXPECT_GT(rgbStats(image, wholeImage(image)).distinctColours, 1u) << "view " << view.name << " is flat";
    }
    // Both stencil-view paths, where this context has stencil texturing, give the same picture.
    if (session->caps.stencilTexturingAvailable()) {
        renderer.views().setStencilPath(StencilViewPath::Texturing);
        renderer.views().render("stencil");
        Image texturing = readDisplay(renderer);
        renderer.views().setStencilPath(StencilViewPath::ReadBack);
        renderer.views().render("stencil");
        EXPECT_TRUE(texturing.rgba == readDisplay(renderer).rgba) << "stencil texturing and read-back differ";
    }
}

// Each fallback that can be forced on a live context draws the unforced images bit for bit: the
// maths is the same on both paths (the CPU turtle composition is bit-identical to the compute
// shader's, which is marked `precise`; the stencil read-back uploads the same integers the
// stencil texturing samples; oasis never uses DSA; SSBOs only serve the compute path today).
// gl33 needs a context of its own: the cli test cli.force_gl33_draws_the_unforced_image.
void expectForcedImagesEqualUnforced(const std::vector<gl::ForcedFallbacks>& cases) {
    Frames unforced;
    {
        auto session = sessionWith({});
        unforced = renderFrames(*session);
    }
    for (const gl::ForcedFallbacks& forced : cases) {
        const std::string name = forced.list();
        SCOPED_TRACE(std::string("--force ") + forced.list());
        gl::Capabilities driver = gl::measureCapabilities();
        bool changesSomething = (forced.noSsbo && driver.driverHasSsbo()) || (forced.noCompute && driver.driverHasCompute()) ||
                                (forced.noStencilTexturing && driver.driverHasStencilTexturing()) || forced.noDsa;
        if (!changesSomething) {  // the driver lacks it already: the unforced session took this fallback
            std::printf("[tier] --force %s: this driver lacks it already, nothing to compare\n", forced.list().c_str());
            continue;
        }
        auto session = sessionWith(forced);
        // The fallback is taken and reported.
        if (forced.noSsbo || forced.noCompute) EXPECT_EQ(session->plantAtlas->path(), PlantInterpretation::Cpu);
        if (forced.noStencilTexturing) EXPECT_EQ(session->renderer->views().stencilPath(), StencilViewPath::ReadBack);
        std::string reported;
        for (const std::string& line : session->fallbacks()) reported += line + "\n";
        for (const char* flag : {"no-ssbo", "no-compute", "no-stencil-texturing", "no-dsa"}) {
            bool forcedThis = forced.list().find(flag) != std::string::npos;
            bool driverHasIt = std::string(flag) == "no-ssbo"      ? session->caps.driverHasSsbo()
                               : std::string(flag) == "no-compute" ? session->caps.driverHasCompute()
                               : std::string(flag) == "no-dsa"     ? true
                                                                   : session->caps.driverHasStencilTexturing();
            if (forcedThis && driverHasIt && std::string(flag) != "no-compute")
                EXPECT_NE(reported.find(std::string("--force ") + flag), std::string::npos) << reported;
        }
        Frames frames = renderFrames(*session);
        EXPECT_TRUE(frames.forward.rgba == unforced.forward.rgba)
            << name << ": forward differs (max " << compareImages(frames.forward, unforced.forward).maxAbs << ")";
        EXPECT_TRUE(frames.deferred.rgba == unforced.deferred.rgba)
            << name << ": deferred differs (max " << compareImages(frames.deferred, unforced.deferred).maxAbs << ")";
        EXPECT_TRUE(frames.overview.rgba == unforced.overview.rgba)
            << name << ": overview differs (max " << compareImages(frames.overview, unforced.overview).maxAbs << ")";
    }
}


TEST_F(DriverTiers, EachForcedFallbackDrawsTheUnforcedImageBitForBit) {
    expectForcedImagesEqualUnforced({{true, false, false, false, false},    // no-ssbo
                                     {false, true, false, false, false},    // no-compute
                                     {false, false, true, false, false},    // no-stencil-texturing
                                     {false, false, false, true, false}});  // no-dsa
}

// The four at once (what softpipe runs: each session costs seconds there).
TEST_F(DriverTiers, AllForcedFallbacksAtOnceDrawTheUnforcedImageBitForBit) {
    expectForcedImagesEqualUnforced({{true, true, true, true, false}});
}

}  // namespace
}  // namespace oasis::gputest
