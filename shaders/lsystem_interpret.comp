// Turtle interpretation of an encoded L-system (uint opcodes, as encodeTurtleProgram makes them)
// into 2D segments, by the three-pass formulation of interpretTurtleByComposition. The bracket
// links (predecessor, depth, output slot of each F) come from the CPU; the variant's define picks
// the pass: local transforms, one pointer-jumping round (dispatched once per round), or emission.
#include "common/turtle_transform.glsl"

layout(local_size_x = 64) in;

const uint OP_FORWARD = 0u, OP_TURN_LEFT = 1u, OP_TURN_RIGHT = 2u;

struct InstructionLink {
    int predecessor;      // the instruction this one continues from; -1: the starting turtle
    uint depth;           // open brackets before the instruction (a [ counts itself)
    uint segmentIndex;    // for an F: its place among the F's (the segment it writes)
};

// std430: a struct of vec2s and scalars has the same 24-byte stride as the C++ structs.
struct Segment {
    vec2 start;
    vec2 end;
    uint depth;
    float distanceFromRoot;
};

layout(std430, binding = 0) readonly buffer Program { uint opcodes[]; };
layout(std430, binding = 1) readonly buffer Links { InstructionLink links[]; };
layout(std430, binding = 2) readonly buffer PredecessorIn { int predecessorIn[]; };
layout(std430, binding = 3) writeonly buffer PredecessorOut { int predecessorOut[]; };
layout(std430, binding = 4) readonly buffer TransformIn { TurtleTransform transformIn[]; };
layout(std430, binding = 5) writeonly buffer TransformOut { TurtleTransform transformOut[]; };
layout(std430, binding = 6) writeonly buffer Segments { Segment segments[]; };

uniform uint instructionCount;
uniform vec2 turnRotation;    // (cos, sin) of the turn angle, computed on the CPU as turtle.cpp does
uniform vec2 startRotation;   // (cos, sin) of the starting heading

#if defined(PASS_LOCAL_TRANSFORMS)
// Pass 2 of turtle.h: one independent transform per instruction; [ and ] are the identity.
TurtleTransform localTransform(uint op) {
    TurtleTransform local = identityTransform();
    if (op == OP_FORWARD) {
        local.translation = vec2(1.0, 0.0);  // the turtle's own frame faces +x
        local.distance = 1.0;
    } else if (op == OP_TURN_LEFT) {
        local.rotation = turnRotation;
    } else if (op == OP_TURN_RIGHT) {
        local.rotation = vec2(turnRotation.x, -turnRotation.y);
    }
    return local;
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= instructionCount) return;
    transformOut[i] = localTransform(opcodes[i]);
    predecessorOut[i] = links[i].predecessor;
}

#elif defined(PASS_COMPOSE_ROUND)
// Pass 3, one round: T[i] = T[pred[i]] * T[i], pred[i] = pred[pred[i]] (double-buffered).
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= instructionCount) return;
    int p = predecessorIn[i];
    transformOut[i] = p < 0 ? transformIn[i] : composeTransforms(transformIn[p], transformIn[i]);
    predecessorOut[i] = p < 0 ? -1 : predecessorIn[p];
}

#elif defined(PASS_EMIT_SEGMENTS)
// One segment per F: from the state before it (its predecessor's) to the state after it.
// transformIn holds every instruction's state after it, relative to the starting turtle.
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= instructionCount || opcodes[i] != OP_FORWARD) return;
    InstructionLink link = links[i];
    TurtleTransform start = identityTransform();
    start.rotation = startRotation;
    TurtleTransform before = composeTransforms(start, link.predecessor < 0 ? identityTransform()
                                                                           : transformIn[link.predecessor]);
    TurtleTransform end = composeTransforms(start, transformIn[i]);
    segments[link.segmentIndex] = Segment(before.translation, end.translation, link.depth, before.distance);
}

#else
#error "lsystem_interpret.comp needs PASS_LOCAL_TRANSFORMS, PASS_COMPOSE_ROUND or PASS_EMIT_SEGMENTS"
#endif
