// Aliasing of the frame's targets by lifetime and format (render/target_aliasing.h).
#include "render/target_aliasing.h"

#include <algorithm>

namespace oasis {

TargetMemory unaliasedTargets() {
    TargetMemory memory;
    for (int t = 0; t < int(Target::Count); ++t) memory[t] = Target(t);
    return memory;
}

TargetMemory aliasTargets(const std::vector<TargetLifetime>& lifetimes,
                          const std::function<unsigned(Target)>& formatOf) {
    TargetMemory memory = unaliasedTargets();
    std::vector<TargetLifetime> byStart = lifetimes;
    std::stable_sort(byStart.begin(), byStart.end(),
                     [](const TargetLifetime& a, const TargetLifetime& b) { return a.first < b.first; });
    // Each memory (named by its first holder) with the step its current holder last uses.
    struct Held {
        Target owner;
        unsigned format;
        int freeAfter;
    };
    std::vector<Held> held;
    for (const TargetLifetime& lifetime : byStart) {
        const unsigned format = formatOf(lifetime.target);
        if (format == 0) continue;
        auto free = std::find_if(held.begin(), held.end(), [&](const Held& h) {
            return h.format == format && h.freeAfter < lifetime.first;
        });
        if (free == held.end()) {
            held.push_back({lifetime.target, format, lifetime.last});
        } else {
            memory[size_t(lifetime.target)] = free->owner;
            free->freeAfter = lifetime.last;
        }
    }
    return memory;
}

std::string lifetimeText(const TargetLifetime& lifetime, const TargetMemory& memory) {
    std::string text = std::string(targetName(lifetime.target)) + " " + std::to_string(lifetime.first) + "-" +
                       (lifetime.last == kBeyondFrame ? std::string("end") : std::to_string(lifetime.last));
    Target owner = memory[size_t(lifetime.target)];
    if (owner != lifetime.target) text += ", memory of " + std::string(targetName(owner));
    return text;
}

}  // namespace oasis
