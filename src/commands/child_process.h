// A child oasis process with a time limit: /proc/self/exe run in a process group of its own, its
// output collected, the whole group stopped at the limit or on an ending signal (compare --driver
// renders each set-up's frame this way).
#pragma once
#include <string>
#include <vector>

namespace oasis {

struct ChildResult {
    int status = 0;
    bool timedOut = false;  // killed at the time limit
    std::string output;  // stdout and stderr together, in the order written
};

// Runs `arguments` (argv[0] first) as /proc/self/exe with `environment` in a process group of its
// own (so a hang is stopped whole: whatever the driver started too), collecting its output; after
// `limitSeconds`, or on an ending signal (held meanwhile: io/interruption.h), the group is
// stopped and the result says it timed out. Throws std::runtime_error when it cannot be started.
ChildResult runChild(const std::vector<std::string>& arguments, const std::vector<std::string>& environment,
                     double limitSeconds);

}  // namespace oasis
