// The frame's targets' lifetimes from the frame graph (frame/target_lifetimes.h).
#include "frame/target_lifetimes.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <cstdio>

#include "frame/frame_graph.h"
#include "render/depth_convention.h"
#include "render/frame_targets.h"

namespace oasis {

std::vector<TargetLifetime> targetLifetimes(const FrameGraph& graph, const FrameSetup& frame,
                                            const std::vector<Target>& beyondFrame) {
    // By (target, scale): the frame's targets, then those at 1/2, then at 1/4.
    constexpr int kDivisors[] = {1, 2, 4};
    constexpr size_t kTargets = size_t(Target::Count);
    std::array<int, 3 * kTargets> first, last;
    first.fill(-1);
    last.fill(-1);
    auto slotOf = [&](Target target, int divisor) {
        const size_t scale = size_t(std::find(std::begin(kDivisors), std::end(kDivisors), divisor) - kDivisors);
        return scale * kTargets + size_t(target);
    };
    int firstRunning = -1;
    for (size_t k = 0; k < graph.steps.size(); ++k) {
        const GraphStep& step = graph.steps[k];
        // The views' steps run after the frame, as each view is drawn: what they touch is in
        // `beyondFrame`, never a borrower.
        if (!step.runs || step.afterFrame) continue;
        if (firstRunning < 0) firstRunning = int(k);
        for (const Access& access : step.pass->accesses(frame)) {
            Target target;
            int divisor;
            if (!targetOf(access.resource, target, divisor)) continue;
            const size_t slot = slotOf(target, divisor);
            if (first[slot] < 0) first[slot] = int(k);
            last[slot] = int(k);
        }
    }
    for (Target target : beyondFrame) {
        size_t t = size_t(target);
        if (first[t] < 0) first[t] = std::max(0, firstRunning);  // written after the frame: never a borrower
        last[t] = kBeyondFrame;
    }
    std::vector<TargetLifetime> lifetimes;
    for (size_t slot = 0; slot < first.size(); ++slot)
        if (first[slot] >= 0)
            lifetimes.push_back({Target(slot % kTargets), first[slot], last[slot], kDivisors[slot / kTargets]});
    return lifetimes;
}

std::string targetLifetimesText(const FrameGraph& graph, const std::vector<TargetLifetime>& lifetimes,
                                const FrameTargets& targets, int divisor) {
    auto passAt = [&](int step) -> std::string {
        if (step == kBeyondFrame) return "(after the frame)";
        return step >= 0 && size_t(step) < graph.steps.size() ? graph.steps[size_t(step)].pass->name() : "?";
    };
    const double mebibyte = 1024.0 * 1024.0;
    std::string text =
        "# targets: first use -> last use (the passes that run), size, memory (whose it takes, who takes it next)\n";
    const TargetMemory& memories = targets.memory(divisor);
    const int width = targets.width(divisor), height = targets.height(divisor);
    for (const TargetLifetime& lifetime : lifetimes) {
        if (lifetime.divisor != divisor) continue;
        const TargetFormat format = targetFormat(targets.layout(), targets.depth(), lifetime.target);
        if (format.internalFormat == 0) continue;  // not stored in this layout
        const Target memory = memories[size_t(lifetime.target)];
        // The target that takes the memory next, after this one's last use, if any.
        const TargetLifetime* next = nullptr;
        for (const TargetLifetime& later : lifetimes)
            if (later.divisor == divisor && later.first > lifetime.last && memories[size_t(later.target)] == memory &&
                (!next || later.first < next->first))
                next = &later;
        const std::string after = next ? targetName(next->target) : "";
        char line[256];
        std::snprintf(line, sizeof(line), "# %-12s %s -> %s, %dx%d x %d B = %.2f MiB%s%s%s%s\n",
                      targetName(lifetime.target), passAt(lifetime.first).c_str(), passAt(lifetime.last).c_str(),
                      width, height, format.bytesPerPixel, double(width) * height * format.bytesPerPixel / mebibyte,
                      memory == lifetime.target ? "" : ", in the memory of ",
                      memory == lifetime.target ? "" : targetName(memory), after.empty() ? "" : ", then lent to ",
                      after.c_str());
        text += line;
    }
    return text;
}

std::string heldTargetMemoryText(const FrameTargets& targets) {
    char held[160];
    std::snprintf(held, sizeof(held), "# targets held after the frame: %.2f MiB (Display included)\n",
                  targets.heldBytes() / (1024.0 * 1024.0));
    return held;
}

}  // namespace oasis
