// Depth and stencil read by drawing (render/depth_stencil_readback.h), the way WebGL 2 and ES
// drivers without GL_NV_read_depth_stencil must read them, against glReadPixels of the same target:
// all 256 stencil values equal; a 24-bit depth within 1 of the stored value (the drawn read goes
// through the sampler's float), a float depth (reversed-z's D32F) equal; a region equal to the same
// part of the whole; and the GL state a pass left untouched by the read.
#include "gpu_test.h"

#include <cmath>

#include "render/depth_stencil_readback.h"

namespace oasis::gputest {
namespace {

class DepthStencilReadback : public GpuTest {};

// Fills the depth-stencil target with 256 cells of 2x1 pixels, cell v holding stencil v and a depth
// spread over [0, 1], ones close to 1 among them (where a 24-bit step is one float ulp).
void paintCells(const FrameTargets& targets) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targets.framebuffer({}, Target::DepthStencil));
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glEnable(GL_SCISSOR_TEST);
    for (int v = 0; v < 256; ++v) {
        glScissor((v % 16) * 2, v / 16, 2, 1);
        float depth = v < 128 ? float(v) / 127.0f : 1.0f - float(v - 127) * 3e-6f;
        glClearBufferfi(GL_DEPTH_STENCIL, 0, depth, v);
    }
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

TEST_F(DepthStencilReadback, DrawnReadsEqualTheDirectReadForEveryStencilValueAndDepth) {
    for (const char* convention : {"standard", "reversed-z"}) {
        SCOPED_TRACE(convention);
        NamedPose pose = defaultPose();
        Renderer renderer(*shaders_, pose.scene);
        renderer.setDepthConvention(*findDepthConvention(convention));
        renderer.configure(32, 16, layoutNamed("standard"));
        const FrameTargets& targets = renderer.targets();
        const bool unorm24 = renderer.paths().depth->name == "standard";
        paintCells(targets);
        DepthStencilRead direct = wholeDepthStencil(targets, false), drawn = wholeDepthStencil(targets, true);
        std::vector<uint8_t> stencil = readStencilRegion(*shaders_, targets, direct);
        EXPECT_EQ(readStencilRegion(*shaders_, targets, drawn), stencil);
        for (int v = 0; v < 256; ++v) ASSERT_EQ(stencil[size_t((v / 16) * 32 + (v % 16) * 2)], v) << "the cells were not painted";
        std::vector<float> depth = readDepthRegion(*shaders_, targets, direct);
        std::vector<float> drawnDepth = readDepthRegion(*shaders_, targets, drawn);
        int offByOne = 0;
        for (size_t i = 0; i < depth.size(); ++i) {
            if (!unorm24) {
                ASSERT_EQ(drawnDepth[i], depth[i]) << "pixel " << i;
                continue;
            }
            long stored = std::lround(double(depth[i]) * 16777215.0), read = std::lround(double(drawnDepth[i]) * 16777215.0);
            ASSERT_LE(std::labs(stored - read), 1) << "pixel " << i;
            offByOne += stored != read;
        }
        std::printf("[depth-stencil drawn] %s: 256 stencil values equal; 24-bit depth off by one at %d of %zu pixels\n",
                    convention, offByOne, depth.size());
        // A region: the same numbers as that part of the whole.
        DepthStencilRead region{Target::DepthStencil, 5, 3, 7, 4, true};
        std::vector<uint8_t> part = readStencilRegion(*shaders_, targets, region);
        std::vector<float> partDepth = readDepthRegion(*shaders_, targets, region);
        for (int y = 0; y < region.height; ++y)
            for (int x = 0; x < region.width; ++x) {
                size_t whole = size_t((region.y + y) * 32 + region.x + x), inPart = size_t(y * region.width + x);
                EXPECT_EQ(part[inPart], stencil[whole]);
                EXPECT_EQ(partDepth[inPart], drawnDepth[whole]);
            }
    }
}

TEST_F(DepthStencilReadback, ADrawnReadLeavesTheStateAPassSet) {
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(32, 16, layoutNamed("standard"));
    const FrameTargets& targets = renderer.targets();
    GLuint framebuffer = targets.framebuffer({Target::Radiance}, Target::DepthStencil);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(3, 4, 20, 10);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_NOTEQUAL, 5, 0x7F);
    glStencilMask(0x80);
    glDepthMask(GL_FALSE);
    glActiveTexture(GL_TEXTURE0 + kUnitSource);
    glBindTexture(GL_TEXTURE_2D, targets.texture(Target::Final));
    glActiveTexture(GL_TEXTURE3);
    readStencilRegion(*shaders_, targets, wholeDepthStencil(targets, true));
    readDepthRegion(*shaders_, targets, wholeDepthStencil(targets, true));
    GLint value = 0, viewport[4] = {};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &value);
    EXPECT_EQ(GLuint(value), framebuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    EXPECT_EQ(viewport[0], 3);
    EXPECT_EQ(viewport[3], 10);
    EXPECT_TRUE(glIsEnabled(GL_BLEND));
    EXPECT_TRUE(glIsEnabled(GL_STENCIL_TEST));
    EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
    glGetIntegerv(GL_BLEND_SRC_RGB, &value);
    EXPECT_EQ(value, GL_SRC_ALPHA);
    glGetIntegerv(GL_STENCIL_FUNC, &value);
    EXPECT_EQ(value, GL_NOTEQUAL);
    glGetIntegerv(GL_STENCIL_VALUE_MASK, &value);
    EXPECT_EQ(value, 0x7F);
    glGetIntegerv(GL_STENCIL_WRITEMASK, &value);
    EXPECT_EQ(value & 0xFF, 0x80);
    GLboolean depthMask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
    EXPECT_FALSE(depthMask);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &value);
    EXPECT_EQ(value, GL_TEXTURE3);
    glActiveTexture(GL_TEXTURE0 + kUnitSource);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &value);
    EXPECT_EQ(GLuint(value), targets.texture(Target::Final));
    // Back to what the other tests expect.
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glDepthMask(GL_TRUE);
}

}  // namespace
}  // namespace oasis::gputest
