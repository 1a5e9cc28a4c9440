// Removal on a signal (io/interruption.h). The handler may run at any moment, so it reads only
// fixed slots published with atomics, and removes with system calls alone (unlink, rmdir,
// getdents64): nothing that allocates or locks.
#include "io/interruption.h"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cstring>

namespace oasis {
namespace {

enum SlotState : int { kFree = 0, kFilling = 1, kLive = 2 };
struct Slot {
    std::atomic<int> state{kFree};
    bool tree = false;
    char path[PATH_MAX];
};
Slot slots[kMaxRemovals];
std::atomic<int> holdDepth{0};
volatile sig_atomic_t held = 0;
// SIGPIPE too: a reader that goes away (oasis caps | head -1) ends oasis quietly, as it ends any
// filter, but not before the temporaries go.
const int kEndingSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};

// Removes everything inside the open directory `fd`, depth first (a handful of levels at most: what
// a driver leaves in a runtime directory).
void emptyDirectory(int fd, int depth) {
    if (depth > 16) return;
    alignas(8) char buffer[4096];
    for (int removed = 1; removed > 0;) {  // until a listing removes nothing (empty, or what stays)
        removed = 0;
        long n = syscall(SYS_getdents64, fd, buffer, sizeof(buffer));
        if (n <= 0) return;
        for (long at = 0; at < n;) {
            struct Entry { ino64_t inode; off64_t offset; unsigned short length; unsigned char type; char name[1]; };
            const Entry* entry = reinterpret_cast<const Entry*>(buffer + at);
            at += entry->length;
            const char* name = entry->name;
            if (name[0] == '.' && (name[1] == 0 || (name[1] == '.' && name[2] == 0))) continue;
            if (unlinkat(fd, name, 0) == 0) { ++removed; continue; }
            int child = openat(fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
            if (child < 0) continue;
            emptyDirectory(child, depth + 1);
            close(child);
            if (unlinkat(fd, name, AT_REMOVEDIR) == 0) ++removed;
        }
        lseek(fd, 0, SEEK_SET);  // entries were removed while listed: list again until none is left
    }
}

bool removeTree(const char* path) {
    int fd = open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd >= 0) {
        emptyDirectory(fd, 0);
        close(fd);
    }
    return rmdir(path) == 0;
}

void removeRegistered() {
    for (Slot& slot : slots) {
        if (slot.state.load() != kLive) continue;
        if (slot.tree) removeTree(slot.path);
        else unlink(slot.path);
    }
}

extern "C" void onEndingSignal(int signal) {
    if (holdDepth.load() > 0) {
        held = signal;
        return;
    }
    removeRegistered();
    struct sigaction fallback {};
    fallback.sa_handler = SIG_DFL;
    sigemptyset(&fallback.sa_mask);
    sigaction(signal, &fallback, nullptr);
    raise(signal);  // delivered when the handler returns: the usual status for the signal
}

}  // namespace

void installInterruptionCleanup() {
    struct sigaction removing {};
    removing.sa_handler = onEndingSignal;
    sigemptyset(&removing.sa_mask);
    for (int signal : kEndingSignals) sigaddset(&removing.sa_mask, signal);  // one handler at a time
    for (int signal : kEndingSignals) {
        struct sigaction previous {};
        // A signal ignored by whoever started oasis (nohup) stays ignored.
        if (sigaction(signal, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
        sigaction(signal, &removing, nullptr);
    }
}

RemovedOnInterrupt::RemovedOnInterrupt(const std::string& path, Kind kind) {
    if (path.size() >= PATH_MAX) return;
    for (int k = 0; k < kMaxRemovals; ++k) {
        int expected = kFree;
        if (!slots[k].state.compare_exchange_strong(expected, kFilling)) continue;
        std::memcpy(slots[k].path, path.c_str(), path.size() + 1);
        slots[k].tree = kind == Kind::DirectoryTree;
        slots[k].state.store(kLive);
        slot_ = k;
        return;
    }
}

RemovedOnInterrupt& RemovedOnInterrupt::operator=(RemovedOnInterrupt&& other) noexcept {
    if (this != &other) {
        release();
        slot_ = other.slot_;
        other.slot_ = -1;
    }
    return *this;
}

void RemovedOnInterrupt::release() {
    if (slot_ >= 0) slots[slot_].state.store(kFree);
    slot_ = -1;
}

InterruptionHeld::InterruptionHeld() { holdDepth.fetch_add(1); }
InterruptionHeld::~InterruptionHeld() { holdDepth.fetch_sub(1); }

int heldSignal() { return held; }

void endForHeldSignal() {
    int signal = held;
    if (signal == 0 || holdDepth.load() > 0) return;  // an outer hold acts when it ends
    onEndingSignal(signal);
}

bool removeDirectoryTree(const std::string& path) { return removeTree(path.c_str()); }

}  // namespace oasis
