// Turtle program encoding and its two interpreters (serial stack loop, three-pass composition).
#include "scene/turtle.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace oasis {
namespace {

constexpr float kDegreesToRadians = float(M_PI / 180.0);

bool toTurtleOp(char symbol, TurtleOp& op) {
    switch (symbol) {
        case 'F': op = TurtleOp::Forward; return true;
        case '+': op = TurtleOp::TurnLeft; return true;
        case '-': op = TurtleOp::TurnRight; return true;
        case '[': op = TurtleOp::Push; return true;
        case ']': op = TurtleOp::Pop; return true;
        default: return false;
    }
}

TurtleOp opAt(const TurtleProgram& program, std::size_t i) { return TurtleOp(program[i]); }

glm::vec2 rotate(glm::vec2 rotation, glm::vec2 v) {
    return {rotation.x * v.x - rotation.y * v.y, rotation.y * v.x + rotation.x * v.y};
}

TurtleTransform rotationBy(float radians) {
    TurtleTransform t;
    t.rotation = {std::cos(radians), std::sin(radians)};
    return t;
}

}  // namespace

TurtleProgram encodeTurtleProgram(std::string_view symbols) {
    TurtleProgram program;
    long depth = 0;
    for (char symbol : symbols) {
        TurtleOp op;
        if (!toTurtleOp(symbol, op)) continue;
        if (op == TurtleOp::Push) ++depth;
        if (op == TurtleOp::Pop && --depth < 0)
            throw std::invalid_argument("turtle program pops more than it pushed");
        program.push_back(uint32_t(op));
    }
    if (depth != 0)
        throw std::invalid_argument("turtle program leaves " + std::to_string(depth) +
                                    " branch(es) open");
    return program;
}

uint64_t countForwardSteps(const TurtleProgram& program) {
    return uint64_t(std::count(program.begin(), program.end(), uint32_t(TurtleOp::Forward)));
}

std::vector<Segment2D> interpretTurtle(const TurtleProgram& program, float angleDegrees,
                                       float startHeadingDegrees) {
    // Double precision: a running sum along a branch gains rounding error with every step (in
    // float, ~7e-5 of the plant's size for the weed at 8 rewrites), and this is the reference.
    struct Turtle {
        glm::dvec2 position{0.0};
        double heading = 0.0;  // radians
        float distance = 0.0f;
    };
    const double degreesToRadians = M_PI / 180.0;
    const double turn = double(angleDegrees) * degreesToRadians;
    Turtle turtle;
    turtle.heading = double(startHeadingDegrees) * degreesToRadians;
    std::vector<Turtle> stack;
    std::vector<Segment2D> segments;
    for (std::size_t i = 0; i < program.size(); ++i) {
        switch (opAt(program, i)) {
            case TurtleOp::Forward: {
                glm::dvec2 end = turtle.position +
                                 glm::dvec2(std::cos(turtle.heading), std::sin(turtle.heading));
                segments.push_back({glm::vec2(turtle.position), glm::vec2(end),
                                    uint32_t(stack.size()), turtle.distance});
                turtle.position = end;
                turtle.distance += 1.0f;
                break;
            }
            case TurtleOp::TurnLeft: turtle.heading += turn; break;
            case TurtleOp::TurnRight: turtle.heading -= turn; break;
            case TurtleOp::Push: stack.push_back(turtle); break;
            case TurtleOp::Pop:
                turtle = stack.back();
                stack.pop_back();
                break;
        }
    }
    return segments;
}

TurtleTransform composeTransforms(const TurtleTransform& outer, const TurtleTransform& inner) {
    TurtleTransform result;
    result.rotation = rotate(outer.rotation, inner.rotation);  // complex product: angles add
    result.translation = outer.translation + rotate(outer.rotation, inner.translation);
    result.distance = outer.distance + inner.distance;
    return result;
}

TurtleLinks linkTurtleInstructions(const TurtleProgram& program) {
    TurtleLinks links;
    links.predecessor.resize(program.size());
    links.depth.resize(program.size());
    std::vector<int32_t> openPushes;
    for (std::size_t i = 0; i < program.size(); ++i) {
        TurtleOp op = opAt(program, i);
        if (op == TurtleOp::Push) openPushes.push_back(int32_t(i));
        links.depth[i] = uint32_t(openPushes.size());
        if (op == TurtleOp::Pop) {
            // The pushed state is the state after the [ itself (a push does not move the turtle).
            links.predecessor[i] = openPushes.back();
            openPushes.pop_back();
        } else {
            links.predecessor[i] = int32_t(i) - 1;
        }
    }
    return links;
}

std::vector<TurtleTransform> localTurtleTransforms(const TurtleProgram& program,
                                                   float angleDegrees) {
    const float turn = angleDegrees * kDegreesToRadians;
    std::vector<TurtleTransform> local(program.size());  // identity for [ and ]
    for (std::size_t i = 0; i < program.size(); ++i) {
        switch (opAt(program, i)) {
            case TurtleOp::Forward:
                local[i].translation = {1.0f, 0.0f};  // the turtle's own frame faces +x
                local[i].distance = 1.0f;
                break;
            case TurtleOp::TurnLeft: local[i] = rotationBy(turn); break;
            case TurtleOp::TurnRight: local[i] = rotationBy(-turn); break;
            case TurtleOp::Push:
            case TurtleOp::Pop: break;
        }
    }
    return local;
}

std::vector<TurtleTransform> composeAlongPredecessors(std::vector<TurtleTransform> local,
                                                      std::vector<int32_t> predecessor,
                                                      int* rounds) {
    // Invariant: transform[i] is the product of the local transforms on the chain from just after
    // predecessor[i] down to i. Each round doubles the chain it covers.
    std::vector<TurtleTransform> transform = std::move(local), nextTransform(transform.size());
    std::vector<int32_t> nextPredecessor(predecessor.size());
    int roundCount = 0;
    auto linked = [](int32_t p) { return p >= 0; };
    bool anyLinked = std::any_of(predecessor.begin(), predecessor.end(), linked);
    while (anyLinked) {
        anyLinked = false;
        for (std::size_t i = 0; i < transform.size(); ++i) {  // one GPU thread per i
            int32_t p = predecessor[i];
            nextTransform[i] = p < 0 ? transform[i] : composeTransforms(transform[p], transform[i]);
            nextPredecessor[i] = p < 0 ? -1 : predecessor[p];
            anyLinked = anyLinked || nextPredecessor[i] >= 0;
        }
        std::swap(transform, nextTransform);
        std::swap(predecessor, nextPredecessor);
        ++roundCount;
    }
    if (rounds) *rounds = roundCount;
    return transform;
}

std::vector<Segment2D> interpretTurtleByComposition(const TurtleProgram& program,
                                                    float angleDegrees,
                                                    float startHeadingDegrees) {
    TurtleLinks links = linkTurtleInstructions(program);
    std::vector<TurtleTransform> after = composeAlongPredecessors(
        localTurtleTransforms(program, angleDegrees), links.predecessor);
    const TurtleTransform start = rotationBy(startHeadingDegrees * kDegreesToRadians);
    std::vector<Segment2D> segments;
    for (std::size_t i = 0; i < program.size(); ++i) {
        if (opAt(program, i) != TurtleOp::Forward) continue;
        int32_t p = links.predecessor[i];
        TurtleTransform before = composeTransforms(start, p < 0 ? TurtleTransform{} : after[p]);
        TurtleTransform end = composeTransforms(start, after[i]);
        segments.push_back({before.translation, end.translation, links.depth[i], before.distance});
    }
    return segments;
}

}  // namespace oasis
