// Turtle interpretation on the GPU: shaders/lsystem_interpret.comp runs the three-pass formulation
// of interpretTurtleByComposition (src/scene/turtle.h), a dispatch per pointer-jumping round, and
// leaves one segment per F in a buffer that is also the plant atlas's vertex buffer.
#pragma once
#include <cstdint>
#include <vector>

#include "gl/objects.h"
#include "render/shader_library.h"
#include "scene/turtle.h"

namespace oasis {

// Compute shaders and shader storage buffers on the current context, no fallback forced
// (gl::Capabilities::computeAvailable: GL 4.3, or the ARB extensions the interpreter needs).
bool contextHasComputeShaders();

// The segments of one plant in a GL buffer: `count` Segment2D records, 24 bytes each (std430).
struct SegmentBuffer {
    gl::Buffer buffer;
    uint32_t count = 0;
};

// Uploads the CPU interpreter's segments in the same layout, so both paths draw the same way.
SegmentBuffer uploadSegments(const std::vector<Segment2D>& segments);
std::vector<Segment2D> readSegments(const SegmentBuffer& segments);

// The bracket matching (pass 1) stays on the CPU, serial with a stack as in turtle.cpp: it is O(n)
// and tiny next to the rest. The CPU also numbers the F's (each one's output slot) and counts the
// pointer-jumping rounds from the longest predecessor chain, so no round needs a read-back.
struct GpuTurtleLinks {
    struct Link { int32_t predecessor; uint32_t depth; uint32_t segmentIndex; };
    std::vector<Link> links;
    uint32_t segmentCount = 0;
    int rounds = 0;  // the rounds composeAlongPredecessors would take
};
GpuTurtleLinks linkForGpu(const TurtleProgram& program);

// Runs the passes on the current context (needs contextHasComputeShaders()). The result is the
// same contract as interpretTurtleByComposition, and bit-identical to it where the GPU rounds
// IEEE single precision as the CPU does (the composition is marked `precise`).
class GpuTurtleInterpreter {
public:
    explicit GpuTurtleInterpreter(ShaderLibrary& shaders) : shaders_(shaders) {}
    SegmentBuffer interpret(const TurtleProgram& program, float angleDegrees,
                            float startHeadingDegrees = 90.0f);

private:
    ShaderLibrary& shaders_;
};

}  // namespace oasis
