// Depth and stencil read back on every context (render/depth_stencil_readback.h).
#include "render/depth_stencil_readback.h"

#include <array>
#include <cmath>
#include <optional>

#include "gl/objects.h"
#include "render/depth_convention.h"
#include "render/pixel_readback.h"
#include "render/texture_units.h"

namespace oasis {
namespace {

// The GL state a drawn read changes, put back as it was: a read in the middle of a frame (the
// pixel history reads after every pass) must leave the next pass the state the last one left.
class KeptState {
public:
    KeptState() {
        for (size_t i = 0; i < kFlags.size(); ++i) enabled_[i] = glIsEnabled(kFlags[i]);
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
        glGetIntegerv(GL_VIEWPORT, viewport_);
        glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
        glActiveTexture(GL_TEXTURE0 + kUnitSource);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &sourceTexture_);
        glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
        glGetBooleanv(GL_COLOR_WRITEMASK, colourMask_);
        glGetIntegerv(GL_STENCIL_FUNC, &stencilFunc_);
        glGetIntegerv(GL_STENCIL_REF, &stencilRef_);
        glGetIntegerv(GL_STENCIL_VALUE_MASK, &stencilValueMask_);
        glGetIntegerv(GL_STENCIL_WRITEMASK, &stencilWriteMask_);
        glGetIntegerv(GL_STENCIL_FAIL, &stencilOps_[0]);
        glGetIntegerv(GL_STENCIL_PASS_DEPTH_FAIL, &stencilOps_[1]);
        glGetIntegerv(GL_STENCIL_PASS_DEPTH_PASS, &stencilOps_[2]);
        glGetIntegerv(GL_BLEND_EQUATION_RGB, &blendEquations_[0]);
        glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &blendEquations_[1]);
        glGetIntegerv(GL_BLEND_SRC_RGB, &blendFuncs_[0]);
        glGetIntegerv(GL_BLEND_DST_RGB, &blendFuncs_[1]);
        glGetIntegerv(GL_BLEND_SRC_ALPHA, &blendFuncs_[2]);
        glGetIntegerv(GL_BLEND_DST_ALPHA, &blendFuncs_[3]);
    }
    ~KeptState() {
        for (size_t i = 0; i < kFlags.size(); ++i) (enabled_[i] ? glEnable : glDisable)(kFlags[i]);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFramebuffer_));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFramebuffer_));
        glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
        // A program deleted while current stays in use until another is: the read's own program
        // ended it, so its name is no program any more.
        glUseProgram(program_ != 0 && glIsProgram(GLuint(program_)) ? GLuint(program_) : 0u);
        glBindVertexArray(GLuint(vertexArray_));
        glActiveTexture(GL_TEXTURE0 + kUnitSource);
        glBindTexture(GL_TEXTURE_2D, GLuint(sourceTexture_));
        glActiveTexture(GLenum(activeTexture_));
        glDepthMask(depthMask_);
        glColorMask(colourMask_[0], colourMask_[1], colourMask_[2], colourMask_[3]);
        glStencilFunc(GLenum(stencilFunc_), stencilRef_, GLuint(stencilValueMask_));
        glStencilMask(GLuint(stencilWriteMask_));
        glStencilOp(GLenum(stencilOps_[0]), GLenum(stencilOps_[1]), GLenum(stencilOps_[2]));
        glBlendEquationSeparate(GLenum(blendEquations_[0]), GLenum(blendEquations_[1]));
        glBlendFuncSeparate(GLenum(blendFuncs_[0]), GLenum(blendFuncs_[1]), GLenum(blendFuncs_[2]), GLenum(blendFuncs_[3]));
    }
    KeptState(const KeptState&) = delete;
    KeptState& operator=(const KeptState&) = delete;

private:
    static constexpr std::array<GLenum, 5> kFlags = {GL_DEPTH_TEST, GL_STENCIL_TEST, GL_BLEND, GL_CULL_FACE, GL_SCISSOR_TEST};
    std::array<GLboolean, 5> enabled_{};
    GLint drawFramebuffer_ = 0, readFramebuffer_ = 0, viewport_[4] = {}, program_ = 0, vertexArray_ = 0;
    GLint activeTexture_ = GL_TEXTURE0, sourceTexture_ = 0;
    GLboolean depthMask_ = GL_TRUE, colourMask_[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    GLint stencilFunc_ = GL_ALWAYS, stencilRef_ = 0, stencilValueMask_ = 0xFF, stencilWriteMask_ = 0xFF;
    GLint stencilOps_[3] = {GL_KEEP, GL_KEEP, GL_KEEP};
    GLint blendEquations_[2] = {GL_FUNC_ADD, GL_FUNC_ADD}, blendFuncs_[4] = {GL_ONE, GL_ZERO, GL_ONE, GL_ZERO};
};

// A colour target of the frame's size (the region is drawn at its own place in it, so a stencil
// attached beside it lines up pixel for pixel) and a framebuffer over it, for one read.
struct DrawnRead {
    KeptState kept;  // made first, destroyed last: the state is put back after the read
    gl::Texture colour;
    gl::Framebuffer framebuffer;
    gl::VertexArray noAttributes = gl::createVertexArray("depth-stencil read-back (no attributes)");

    DrawnRead(const FrameTargets& targets, GLenum format, const char* label, std::optional<Target> stencil,
              int divisor) {
        colour = gl::createTargetTexture(label, format, targets.width(divisor), targets.height(divisor));
        framebuffer = gl::createFramebuffer(label);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.name());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour.name(), 0);
        if (stencil)
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                                   targets.texture(*stencil, divisor), 0);
        GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
        glDrawBuffers(1, &drawBuffer);
    }
    void begin(const DepthStencilRead& r) const {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.name());
        glViewport(r.x, r.y, r.width, r.height);
        glDisable(GL_DEPTH_TEST);
        glDepthMask(GL_FALSE);
        glDisable(GL_CULL_FACE);
        glDisable(GL_SCISSOR_TEST);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glBindVertexArray(noAttributes.name());
    }
    // The region's red channel as drawn: ES reads a colour buffer as RGBA (floats from a float
    // buffer, EXT_color_buffer_float; bytes from a unorm one).
    template <typename Value>
    std::vector<Value> readRed(const DepthStencilRead& r, GLenum type) const {
        std::vector<Value> rgba(size_t(r.width) * size_t(r.height) * 4);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.name());
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(r.x, r.y, r.width, r.height, GL_RGBA, type, rgba.data());
        std::vector<Value> red(size_t(r.width) * size_t(r.height));
        for (size_t i = 0; i < red.size(); ++i) red[i] = rgba[4 * i];
        return red;
    }
};

std::vector<float> drawDepth(ShaderLibrary& shaders, const FrameTargets& targets, const DepthStencilRead& r) {
    DrawnRead read(targets, GL_R32F, "depth read-back (drawn)", std::nullopt, r.divisor);
    read.begin(r);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glActiveTexture(GL_TEXTURE0 + kUnitSource);
    glBindTexture(GL_TEXTURE_2D, targets.texture(r.target, r.divisor));
    glUseProgram(shaders.program("readback.depth"));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<float> depth = read.readRed<float>(r, GL_FLOAT);
    // A 24-bit depth comes back as the sampler's float of d / (2^24 - 1), whose rounding is the
    // driver's: near 1 a float step is a 24-bit step, so it lands on d or a neighbour (llvmpipe: d + 1
    // for most d). Taken to the nearest 24-bit value and converted as glReadPixels converts, it is
    // within one step of the stored depth; a float depth is exact.
    if (targetFormat(targets.layout(), targets.depth(), r.target).internalFormat == GL_DEPTH24_STENCIL8)
        for (float& d : depth) d = float(std::round(double(d) * 16777215.0) / 16777215.0);
    return depth;
}

std::vector<uint8_t> drawStencil(ShaderLibrary& shaders, const FrameTargets& targets, const DepthStencilRead& r) {
    DrawnRead read(targets, GL_R8, "stencil read-back (drawn)", r.target, r.divisor);
    read.begin(r);
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, zero);
    // Each bit where the stencil test finds it set adds 2^bit / 255: the sum, exact in 8-bit unorm,
    // is the stencil value. The stencil itself is only tested, never written.
    glEnable(GL_STENCIL_TEST);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilMask(0x00);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    GLuint program = shaders.program("readback.stencil");
    glUseProgram(program);
    GLint bitValue = glGetUniformLocation(program, "stencilBitValue");
    for (int bit = 0; bit < 8; ++bit) {
        glStencilFunc(GL_EQUAL, 1 << bit, GLuint(1 << bit));
        glUniform1f(bitValue, float(1 << bit) / 255.0f);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    return read.readRed<uint8_t>(r, GL_UNSIGNED_BYTE);
}

}  // namespace

std::vector<float> readDepthRegion(ShaderLibrary& shaders, const FrameTargets& targets, const DepthStencilRead& read) {
    if (read.drawn) return drawDepth(shaders, targets, read);
    std::vector<float> depth(size_t(read.width) * size_t(read.height));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.framebuffer({}, read.target, read.divisor));
    readDepthFloats(read.x, read.y, read.width, read.height, depth.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return depth;
}

std::vector<uint8_t> readStencilRegion(ShaderLibrary& shaders, const FrameTargets& targets,
                                       const DepthStencilRead& read) {
    if (read.drawn) return drawStencil(shaders, targets, read);
    std::vector<uint8_t> stencil(size_t(read.width) * size_t(read.height));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.framebuffer({}, read.target, read.divisor));
    readStencilBytes(read.x, read.y, read.width, read.height, stencil.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return stencil;
}

}  // namespace oasis
