// Bad input: sizes beyond GL_MAX_TEXTURE_SIZE, and sizes inside it whose targets would exceed
// kMaxTargetBytes, throw naming the size before anything is allocated (and the renderer recovers),
// a 1x1 frame renders in both pipelines without NaN, and a shader reload with a broken file keeps
// the previous programs (same image) and names the file; restoring it reloads cleanly.
#include "frame/frame_readback.h"
#include "gpu_test.h"
#include "shader_dir_copy.h"

#include <filesystem>

#include "debug/debug_views.h"
#include "render/frame_targets.h"

namespace oasis::gputest {
namespace {

namespace fs = std::filesystem;

class BadInput : public GpuTest {};

TEST_F(BadInput, SizeBeyondMaxTextureSizeThrowsNamingTheSize) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    ASSERT_GT(maxSize, 0);
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(64, 36, layoutNamed("standard"));
    const std::pair<int, int> badSizes[] = {{maxSize + 1, 16}, {16, maxSize + 1}, {2 * maxSize, 2 * maxSize}, {0, 16}};
    for (auto [width, height] : badSizes) {
        std::string size = std::to_string(width) + "x" + std::to_string(height);
        try {
            renderer.configure(width, height, layoutNamed("full"));
            ADD_FAILURE() << "configure(" << size << ") did not throw (GL_MAX_TEXTURE_SIZE " << maxSize << ")";
        } catch (const std::runtime_error& error) {
            EXPECT_NE(std::string(error.what()).find(size), std::string::npos)
                << "the message does not name the size " << size << ": " << error.what();
        } catch (const std::exception& error) {
            ADD_FAILURE() << "configure(" << size << ") threw something other than std::runtime_error: " << error.what();
        }
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << "a rejected size reached GL: " << size;
    }
    // A valid size afterwards works again.
    renderer.configure(64, 36, layoutNamed("standard"));
    EXPECT_TRUE(hasContent(renderFinal(renderer, pose.scene, PipelineKind::Deferred)));
    // The limit itself is a valid size.
    renderer.configure(maxSize, 4, layoutNamed("standard"));
    EXPECT_EQ(renderer.targets().width(), maxSize);
    renderer.configure(64, 36, layoutNamed("standard"));
}

// A size every side of which GL_MAX_TEXTURE_SIZE allows, but whose targets (all of the layout's
// plus Display) would need more than kMaxTargetBytes: refused with the size and the GiB it needs,
// before any texture is made (software drivers may abort instead of reporting GL_OUT_OF_MEMORY).
TEST_F(BadInput, SizeWithinMaxTextureSizeButBeyondTheMemoryLimitThrows) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(64, 36, layoutNamed("standard"));
    for (const char* layoutName : {"full", "standard"}) {
        const GBufferLayout& layout = layoutNamed(layoutName);
        int bytesPerPixel = 4;  // Display
        for (int t = 0; t < int(Target::Count); ++t) bytesPerPixel += layout.format(Target(t)).bytesPerPixel;
        // The fewest rows of the widest frame that pass the limit.
        const double rows = std::floor(kMaxTargetBytes / (double(maxSize) * bytesPerPixel)) + 1.0;
        if (rows > maxSize) {
            std::printf("[bad input] %s: %dx%d needs only %.1f GiB, within the limit: nothing to refuse here\n",
                        layoutName, maxSize, maxSize, double(maxSize) * maxSize * bytesPerPixel / double(1u << 30));
            continue;
        }
        const int height = int(rows);
        const std::string size = std::to_string(maxSize) + "x" + std::to_string(height);
        SCOPED_TRACE(std::string(layoutName) + " " + size);
        const int liveBefore = gl::liveObjectCount();
        try {
            renderer.configure(maxSize, height, layout);
            ADD_FAILURE() << "configure(" << size << ") did not throw (" << bytesPerPixel << " bytes per pixel)";
        } catch (const std::runtime_error& error) {
            std::printf("[bad input] %s: %s refused: %s\n", layoutName, size.c_str(), error.what());
            EXPECT_NE(std::string(error.what()).find(size), std::string::npos) << error.what();
            EXPECT_NE(std::string(error.what()).find("GiB"), std::string::npos) << error.what();
        }
        EXPECT_EQ(gl::liveObjectCount(), liveBefore) << "objects made for a refused size";
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << "a refused size reached GL";
        // One row fewer is within the limit: the check is the memory, not the side.
        EXPECT_LE(double(maxSize) * (height - 1) * bytesPerPixel, kMaxTargetBytes);
    }
    EXPECT_EQ(renderer.targets().width(), 64) << "the old targets were not kept";
    EXPECT_TRUE(hasContent(renderFinal(renderer, pose.scene, PipelineKind::Deferred)));
}

TEST_F(BadInput, OneByOneFrameRendersInBothPipelinesWithoutNaN) {
    for (const NamedPose& pose : {defaultPose(), poseNamed("up"), poseNamed("down")}) {
        Renderer renderer(*shaders_, pose.scene);
        for (const char* layout : {"full", "standard"}) {
            SCOPED_TRACE(pose.name + " " + layout);
            renderer.configure(1, 1, layoutNamed(layout));
            Image forward = renderFinal(renderer, pose.scene, PipelineKind::Forward);
            EXPECT_EQ(countNonFinite(readTarget(renderer, Target::Final)), 0);
            EXPECT_EQ(countNonFinite(readDepth(renderer)), 0);
            Image deferred = renderFinal(renderer, pose.scene, PipelineKind::Deferred);
            const std::vector<uint8_t> stencil = readStencil(renderer);
            for (Target target : {Target::Albedo, Target::Normal, Target::Position, Target::Info, Target::Final})
                EXPECT_EQ(countNonFiniteWritten(readTarget(renderer, target), target, stencil, false), 0) << targetName(target);
            EXPECT_EQ(countNonFinite(readDepth(renderer)), 0);
            ASSERT_EQ(forward.width, 1);
            ASSERT_EQ(deferred.height, 1);
            // The one pixel is a real colour (opaque, not black) and the pipelines agree on it.
            EXPECT_EQ(forward.rgba[3], 255);
            EXPECT_GT(int(forward.rgba[0]) + forward.rgba[1] + forward.rgba[2], 30) << "black 1x1 frame";
            EXPECT_LE(compareImages(forward, deferred).maxAbs, 3);
            // Views and the overview (tiles smaller than a pixel) must not fail either.
            for (const DebugView& view : debugViews()) renderer.views().render(view.name);
            renderer.views().render(kOverviewName);
            EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        }
    }
}

// Unknown names are rejected with std::invalid_argument naming what exists: a debug view name in
// renderView, a pass name in renderFrame's stopBefore (per pipeline: "SkyPass.forward" is a
// forward pass only). The renderer keeps working afterwards.
TEST_F(BadInput, UnknownViewAndPassNamesThrowInvalidArgument) {
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(64, 36, layoutNamed("standard"));
    renderer.setPipeline(PipelineKind::Deferred);
    renderer.renderFrame(pose.scene);
    auto expectInvalid = [](const std::function<void()>& call, const std::string& mustMention, const std::string& what) {
        try {
            call();
            ADD_FAILURE() << what << " did not throw";
        } catch (const std::invalid_argument& error) {
            EXPECT_NE(std::string(error.what()).find(mustMention), std::string::npos)
                << what << ": the message does not mention " << mustMention << ": " << error.what();
        } catch (const std::exception& error) {
            ADD_FAILURE() << what << " threw something other than std::invalid_argument: " << error.what();
        }
    };
    expectInvalid([&] { renderer.views().render("no-such-view"); }, "reflection", "renderView(\"no-such-view\")");
    expectInvalid([&] { renderer.views().render(""); }, "final", "renderView(\"\")");
    expectInvalid([&] { renderer.renderFrame(pose.scene, "NoSuchPass"); }, "WaterCompositePass",
                  "renderFrame(stopBefore \"NoSuchPass\")");
    expectInvalid([&] { renderer.renderFrame(pose.scene, "SkyPass.forward"); }, "LightingPass",
                  "deferred renderFrame(stopBefore \"SkyPass.forward\")");
    renderer.setPipeline(PipelineKind::Forward);
    expectInvalid([&] { renderer.renderFrame(pose.scene, "LightingPass"); }, "SkyPass.forward",
                  "forward renderFrame(stopBefore \"LightingPass\")");
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    EXPECT_TRUE(hasContent(renderFinal(renderer, pose.scene, PipelineKind::Deferred)));
}

class ShaderReload : public GpuTest {
protected:
    struct Frames {
        Image forward, deferred;
    };
    Frames render(Renderer& renderer, const SceneSettings& scene) {
        Frames frames;
        frames.forward = renderFinal(renderer, scene, PipelineKind::Forward);
        frames.deferred = renderFinal(renderer, scene, PipelineKind::Deferred);
        return frames;
    }
    void expectSame(const Frames& a, const Frames& b, const std::string& when) {
        EXPECT_EQ(compareImages(a.forward, b.forward).maxAbs, 0) << "forward image changed " << when;
        EXPECT_EQ(compareImages(a.deferred, b.deferred).maxAbs, 0) << "deferred image changed " << when;
    }
    // Breaks `file` (relative to the shader dir), reloads, checks the failures and the images,
    // restores it and reloads again. `programs` are the variants that include the file.
    void breakAndRestore(const std::string& file, const std::vector<std::string>& programs) {
        SCOPED_TRACE("broken " + file);
        ShaderDirCopy copy(shaderDir_);
        ShaderLibrary library(copy.root.string(), glslDialectForCurrentContext());
        NamedPose pose = defaultPose();
        Renderer renderer(library, pose.scene);
        renderer.configure(160, 90, layoutNamed("standard"));
        Frames before = render(renderer, pose.scene);
        ASSERT_TRUE(hasContent(before.forward));
        ASSERT_TRUE(hasContent(before.deferred));
        ASSERT_TRUE(library.reloadAll().empty()) << "reloading the unmodified copy failed";
        const int liveBefore = gl::liveObjectCount();

        const fs::path path = copy.root / file;
        const std::string original = readText(path);
        ASSERT_FALSE(original.empty());
        ASSERT_EQ(original.back(), '\n');
        const int brokenLine = int(std::count(original.begin(), original.end(), '\n')) + 1;
        writeText(path, original + "this is not GLSL;\n");

        std::vector<std::string> failures = library.reloadAll();
        ASSERT_FALSE(failures.empty()) << "a broken " << file << " reloaded without complaint";
        EXPECT_EQ(failures.size(), programs.size()) << "one failure per program that includes " << file;
        for (const std::string& program : programs) {
            bool named = std::any_of(failures.begin(), failures.end(),
                                     [&](const std::string& f) { return f.find("program " + program + ":") != std::string::npos; });
            EXPECT_TRUE(named) << "no failure names program " << program;
        }
        for (const std::string& failure : failures) {
            EXPECT_NE(failure.find(file + ":" + std::to_string(brokenLine)), std::string::npos)
                << "failure does not name " << file << ":" << brokenLine << ":\n" << failure;
        }
        EXPECT_EQ(gl::liveObjectCount(), liveBefore) << "a failed reload leaked or dropped objects";
        expectSame(before, render(renderer, pose.scene), "after a failed reload");

        writeText(path, original);
        std::vector<std::string> afterRestore = library.reloadAll();
        EXPECT_TRUE(afterRestore.empty()) << "reload after restoring failed: " << (afterRestore.empty() ? "" : afterRestore[0]);
        EXPECT_EQ(gl::liveObjectCount(), liveBefore);
        expectSame(before, render(renderer, pose.scene), "after restoring");
    }
};

TEST_F(ShaderReload, BrokenTerrainFragKeepsPreviousProgramsUntilRestored) {
    // The default frame (camera above the lake, reflections on, the sun up) builds all four terrain
    // variants, the shadow caster and the heights pass; the forward ones are those of the light path the context
    // picks (ssbo on llvmpipe), the direct one with the tone map fused (a whole frame).
    breakAndRestore("terrain.frag", {"terrain.gbuffer", "terrain.forward.tonemapped.lights-ssbo", "terrain.gbuffer.mirrored",
                                     "terrain.forward.mirrored.lights-ssbo", "terrain.shadow", "terrain.heights"});
}

TEST_F(ShaderReload, BrokenIncludedFileIsNamedInEveryProgramThatIncludesIt) {
    // common/sky.glsl reaches every program that includes common/lighting.glsl: the forward terrain
    // and vegetation variants (through emit_surface.glsl; the vegetation pass builds its program even
    // without an atlas to draw), both sky variants, both lighting variants and the water
    // composite. The G-buffer terrain and vegetation variants include lighting.glsl only inside
    // emit_surface.glsl's inactive OUTPUT_FORWARD branch, so the broken line is not compiled there. Only programs already
    // built are reloaded (the debug views built here, "final", do not include it). Whole frames
    // fuse the tone map: the direct shading programs are the ".tonemapped" variants.
    breakAndRestore("common/sky.glsl", {"terrain.forward.tonemapped.lights-ssbo", "terrain.forward.mirrored.lights-ssbo",
                                        "vegetation.forward.tonemapped.lights-ssbo",
                                        "vegetation.forward.mirrored.lights-ssbo", "sky.forward.tonemapped",
                                        "sky.forward.mirrored", "lighting.tonemapped", "lighting.mirrored",
                                        "water.composite.tonemapped"});
}

}  // namespace
}  // namespace oasis::gputest
