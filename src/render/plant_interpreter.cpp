// GPU turtle interpretation: CPU links, then local transforms, pointer jumping and emission.
#include "render/plant_interpreter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "gl/capabilities.h"

namespace oasis {
namespace {

static_assert(sizeof(Segment2D) == 24, "Segment2D must match the std430 Segment of lsystem_interpret.comp");
static_assert(sizeof(GpuTurtleLinks::Link) == 12, "Link must match InstructionLink of lsystem_interpret.comp");
constexpr size_t kTransformStride = 24;  // std430 TurtleTransform: vec2, vec2, float, padded to 8
constexpr GLuint kWorkGroupSize = 64;    // local_size_x of lsystem_interpret.comp

// Storage-buffer bindings, as declared in lsystem_interpret.comp.
enum Binding : GLuint {
    kProgram = 0, kLinks = 1, kPredecessorIn = 2, kPredecessorOut = 3,
    kTransformIn = 4, kTransformOut = 5, kSegments = 6,
};

gl::Buffer storageBuffer(const std::string& label, size_t bytes, const void* data) {
    // Made through a target every context has: the CPU path uses these too, where SSBOs may not exist.
    gl::Buffer buffer = gl::createBuffer(label);
    glBindBuffer(GL_COPY_WRITE_BUFFER, buffer.name());
    // Never zero bytes: a plant without an F still binds a valid buffer.
    glBufferData(GL_COPY_WRITE_BUFFER, GLsizeiptr(std::max<size_t>(bytes, 4)), data, GL_STATIC_DRAW);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    return buffer;
}

// (cos, sin) exactly as turtle.cpp's rotationBy computes them, so both paths turn alike.
glm::vec2 rotationFor(float degrees) {
    const float radians = degrees * float(M_PI / 180.0);
    return {std::cos(radians), std::sin(radians)};
}

void setUniforms(GLuint program, uint32_t count, float angleDegrees, float startHeadingDegrees) {
    glm::vec2 turn = rotationFor(angleDegrees), start = rotationFor(startHeadingDegrees);
    glUniform1ui(glGetUniformLocation(program, "instructionCount"), count);
    glUniform2f(glGetUniformLocation(program, "turnRotation"), turn.x, turn.y);
    glUniform2f(glGetUniformLocation(program, "startRotation"), start.x, start.y);
}

void dispatch(GLuint program, uint32_t count, float angleDegrees, float startHeadingDegrees,
              GLbitfield barrier = GL_SHADER_STORAGE_BARRIER_BIT) {
    glUseProgram(program);
    setUniforms(program, count, angleDegrees, startHeadingDegrees);
    glDispatchCompute((count + kWorkGroupSize - 1) / kWorkGroupSize, 1, 1);
    glMemoryBarrier(barrier);
}

}  // namespace

bool contextHasComputeShaders() { return gl::measureCapabilities().computeAvailable(); }

SegmentBuffer uploadSegments(const std::vector<Segment2D>& segments) {
    SegmentBuffer result;
    result.buffer = storageBuffer("plant segments (cpu turtle)", segments.size() * sizeof(Segment2D), segments.data());
    result.count = uint32_t(segments.size());
    return result;
}

std::vector<Segment2D> readSegments(const SegmentBuffer& segments) {
    std::vector<Segment2D> result(segments.count);
    glBindBuffer(GL_COPY_READ_BUFFER, segments.buffer.name());
    gl::readBufferData(GL_COPY_READ_BUFFER, GLsizeiptr(result.size() * sizeof(Segment2D)), result.data());
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    return result;
}

GpuTurtleLinks linkForGpu(const TurtleProgram& program) {
    TurtleLinks links = linkTurtleInstructions(program);
    GpuTurtleLinks result;
    result.links.resize(program.size());
    std::vector<uint32_t> ancestors(program.size());  // length of each predecessor chain
    uint32_t longest = 0;
    for (size_t i = 0; i < program.size(); ++i) {
        int32_t p = links.predecessor[i];  // always earlier than i
        ancestors[i] = p < 0 ? 0 : ancestors[size_t(p)] + 1;
        longest = std::max(longest, ancestors[i]);
        bool forward = TurtleOp(program[i]) == TurtleOp::Forward;
        result.links[i] = {p, links.depth[i], forward ? result.segmentCount : 0};
        result.segmentCount += forward;
    }
    // After r rounds pred[i] is the ancestor 2^r steps up; all are gone once 2^r exceeds the longest.
    while ((uint64_t(1) << result.rounds) <= longest) ++result.rounds;
    return result;
}

SegmentBuffer GpuTurtleInterpreter::interpret(const TurtleProgram& program, float angleDegrees,
                                              float startHeadingDegrees) {
    GLint maxGroups = 0;
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &maxGroups);
    if (program.size() > size_t(maxGroups) * kWorkGroupSize)
        throw std::runtime_error("turtle program of " + std::to_string(program.size()) +
                                 " instructions exceeds one compute dispatch");
    const uint32_t n = uint32_t(program.size());
    GpuTurtleLinks links = linkForGpu(program);
    gl::Buffer opcodes = storageBuffer("turtle opcodes (ssbo)", program.size() * sizeof(uint32_t), program.data());
    gl::Buffer linkBuffer = storageBuffer("turtle bracket links (ssbo)",
                                         links.links.size() * sizeof(GpuTurtleLinks::Link), links.links.data());
    gl::Buffer predecessors[2] = {storageBuffer("turtle predecessors A (ssbo)", n * sizeof(int32_t), nullptr),
                                  storageBuffer("turtle predecessors B (ssbo)", n * sizeof(int32_t), nullptr)};
    gl::Buffer transforms[2] = {storageBuffer("turtle transforms A (ssbo)", n * kTransformStride, nullptr),
                                storageBuffer("turtle transforms B (ssbo)", n * kTransformStride, nullptr)};
    SegmentBuffer segments;
    segments.buffer = storageBuffer("plant segments (gpu turtle, ssbo)", links.segmentCount * sizeof(Segment2D), nullptr);
    segments.count = links.segmentCount;
    if (n == 0) return segments;

    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kProgram, opcodes.name());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLinks, linkBuffer.name());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSegments, segments.buffer.name());
    auto bindRound = [&](int from) {  // reads buffers[from], writes buffers[1 - from]
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPredecessorIn, predecessors[from].name());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTransformIn, transforms[from].name());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPredecessorOut, predecessors[1 - from].name());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTransformOut, transforms[1 - from].name());
    };
    bindRound(1);  // the local pass fills buffers[0]
    dispatch(shaders_.program("lsystem.local"), n, angleDegrees, startHeadingDegrees);
    int current = 0;
    for (int round = 0; round < links.rounds; ++round, current = 1 - current) {
        bindRound(current);
        dispatch(shaders_.program("lsystem.compose"), n, angleDegrees, startHeadingDegrees);
    }
    bindRound(current);  // the emission reads the composed transforms as its input
    // The segments are next drawn as vertex attributes or read back.
    dispatch(shaders_.program("lsystem.segments"), n, angleDegrees, startHeadingDegrees,
             GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    for (GLuint binding = kProgram; binding <= kSegments; ++binding)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
    glUseProgram(0);
    return segments;
}

}  // namespace oasis
