// Turtle interpretation of L-system strings: a compact opcode program (what a GPU buffer will hold)
// and two interpreters that must agree: the classic serial stack loop, and a three-pass formulation
// (bracket links, local transforms, composition) that a compute shader can run in parallel.
#pragma once
#include <cstdint>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace oasis {

// One 32-bit word per instruction so a shader indexes it directly; symbols the turtle ignores
// (X and other growth markers) are dropped. F: forward one unit drawing; +: turn left (counter-
// clockwise) by the angle; -: turn right; [: push the turtle; ]: pop it.
enum class TurtleOp : uint32_t { Forward = 0, TurnLeft = 1, TurnRight = 2, Push = 3, Pop = 4 };
using TurtleProgram = std::vector<uint32_t>;

// Throws std::invalid_argument when the brackets do not balance, so no interpreter (and no shader)
// ever has to cope with popping an empty stack.
TurtleProgram encodeTurtleProgram(std::string_view symbols);
uint64_t countForwardSteps(const TurtleProgram& program);

// One drawn F. The attributes feed the brown-to-green colouring later.
struct Segment2D {
    glm::vec2 start{0.0f};
    glm::vec2 end{0.0f};
    uint32_t depth = 0;              // brackets enclosing the F: 0 on the main axis
    float distanceFromRoot = 0.0f;   // F steps along the branch path from the root to `start`
};

// Serial reference: a stack of turtle states. Headings in degrees, counter-clockwise from +x;
// the default 90 grows the plant up +y. One segment per F, in program order.
std::vector<Segment2D> interpretTurtle(const TurtleProgram& program, float angleDegrees,
                                       float startHeadingDegrees = 90.0f);

// --- The parallel-friendly formulation -----------------------------------------------------------
// The turtle state after instruction i is a 2D rigid transform (rotation, translation) plus the
// distance walked. Every instruction continues from the state after one earlier instruction, its
// predecessor: i - 1, except that ] continues from its matching [ (a closed branch leaves the
// turtle where the branch began). So state_after(i) = state_after(predecessor(i)) * local(i), and
// the predecessors form a forest whose root-to-node products are the states.
//
// Cost, n instructions, L the longest predecessor chain (the main axis; L <= n):
//   serial loop:           O(n) work, O(n) span, O(bracket depth) stack.
//   pass 1 links + depth:  depth is an exclusive prefix sum of +1/-1 over brackets; a stable sort of
//                          the brackets by depth puts each ] right after its [. O(n) work,
//                          O(log n) span. (Run serially with a stack here.)
//   pass 2 local:          one independent transform per instruction: O(n) work, O(1) span.
//   pass 3 compose:        pointer jumping: each round every i does T[i] = T[pred[i]] * T[i],
//                          pred[i] = pred[pred[i]]; ceil(log2 L) rounds, so O(n log L) work and
//                          O(log L) span, two buffers of n transforms. Run round by round here,
//                          double-buffered, exactly as a dispatch per round would.
// E.g. the fractal plant after 6 rewrites: n = 21063, L = 225, 8 rounds (8 rewrites: n = 338215,
// L = 813, 10 rounds). The products are formed as a balanced tree, so float rounding grows with
// log L rather than L: in float they stay within ~3e-7 of the plant's size of a double-precision
// turtle up to 8 rewrites, where a float serial loop drifts to ~7e-5 (the weed).
// A linear-work alternative exists because headings and positions are sums in abelian groups
// (turn counts, displacement vectors), where a closed branch can be cancelled by subtracting its own
// level's sum at ]: that needs a segmented scan per depth level, more passes for the same result.

struct TurtleTransform {
    glm::vec2 rotation{1.0f, 0.0f};     // (cos, sin) of the heading change
    glm::vec2 translation{0.0f};
    float distance = 0.0f;              // F steps walked
};
// outer * inner: apply inner in outer's frame (inner happens after outer).
TurtleTransform composeTransforms(const TurtleTransform& outer, const TurtleTransform& inner);

struct TurtleLinks {
    std::vector<int32_t> predecessor;  // -1: continues from the starting turtle
    std::vector<uint32_t> depth;       // open brackets before the instruction (a [ counts itself)
};
// Pass 1.
TurtleLinks linkTurtleInstructions(const TurtleProgram& program);
// Pass 2.
std::vector<TurtleTransform> localTurtleTransforms(const TurtleProgram& program, float angleDegrees);
// Pass 3: returns each instruction's state after it, relative to the starting turtle.
// `rounds`, when given, receives the number of pointer-jumping rounds taken.
std::vector<TurtleTransform> composeAlongPredecessors(std::vector<TurtleTransform> local,
                                                      std::vector<int32_t> predecessor,
                                                      int* rounds = nullptr);

// The three passes, then one segment per F; same output contract as interpretTurtle.
std::vector<Segment2D> interpretTurtleByComposition(const TurtleProgram& program,
                                                    float angleDegrees,
                                                    float startHeadingDegrees = 90.0f);

}  // namespace oasis
