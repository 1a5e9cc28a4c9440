// What oasis removes when a signal ends it: SIGINT, SIGTERM, SIGHUP and SIGPIPE remove the temporaries and
// directories oasis made that are not finished yet (registered here while they exist), then end the
// process with that signal's usual status. While a child process runs (compare --driver), a signal
// is held instead, so that the caller can stop the child first and then end (endForHeldSignal).
#pragma once
#include <string>

namespace oasis {

// Installed once, at the start of main(). Without it nothing is removed (the signals keep their
// default action), which is what the tests' binaries get.
void installInterruptionCleanup();

// Something removed if a signal ends oasis while it is registered: a file, or a directory with
// everything in it. Registered from before it is created until it is renamed or removed; at most
// kMaxRemovals at once (past that, a path is not registered and `registered()` is false).
class RemovedOnInterrupt {
public:
    enum class Kind { File, DirectoryTree };
    RemovedOnInterrupt() = default;
    RemovedOnInterrupt(const std::string& path, Kind kind);
    ~RemovedOnInterrupt() { release(); }
    RemovedOnInterrupt(RemovedOnInterrupt&& other) noexcept : slot_(other.slot_) { other.slot_ = -1; }
    RemovedOnInterrupt& operator=(RemovedOnInterrupt&& other) noexcept;
    RemovedOnInterrupt(const RemovedOnInterrupt&) = delete;
    RemovedOnInterrupt& operator=(const RemovedOnInterrupt&) = delete;
    void release();  // no longer removed on a signal (renamed into place, or already removed)
    bool registered() const { return slot_ >= 0; }

private:
    int slot_ = -1;
};
constexpr int kMaxRemovals = 32;

// While one exists, an ending signal is held (noted, not acted on).
class InterruptionHeld {
public:
    InterruptionHeld();
    ~InterruptionHeld();
    InterruptionHeld(const InterruptionHeld&) = delete;
    InterruptionHeld& operator=(const InterruptionHeld&) = delete;
};
// The signal held since the last one was acted on, or 0.
int heldSignal();
// Removes what is registered and ends the process with the held signal; returns if none is held or
// a hold is still in force.
void endForHeldSignal();

// Removes a directory and everything in it (as a signal would); false if something stayed.
bool removeDirectoryTree(const std::string& path);

}  // namespace oasis
