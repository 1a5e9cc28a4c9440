// Whole-or-nothing file output: stage to a temporary beside the target, check, rename.
#include "io/file_output.h"
#include "io/printable_text.h"

#include "io/interruption.h"

#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <optional>

namespace oasis {
namespace {

// How one file reaches its target.
struct Staged {
    std::string path;       // as given: what messages name
    std::string target;     // what is replaced (a link's target, so that the link stays)
    std::string temporary;  // the complete new file; empty while none exists
    bool inPlace = false;   // written straight into `path` (it cannot be replaced)
    int keptMode = -1;      // the replaced file's permission bits, given to its replacement
    RemovedOnInterrupt removal;  // the temporary, removed if a signal ends oasis before the rename
};

bool fail(const std::string& path, const std::string& why, std::string& error) {
    error = "cannot write " + printableText(path) + ": " + why;
    return false;
}

std::string directoryOf(const std::string& path) {
    size_t slash = path.rfind('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string baseNameOf(const std::string& path) {
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

bool startsWith(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

bool isPseudoPath(const std::string& path) {
    return path == "/dev" || path == "/proc" || startsWith(path, "/dev/") || startsWith(path, "/proc/");
}

// /dev/stdout and /dev/fd/N are links into /proc/self/fd: renaming over one would replace the link
// (or fail), not write to the descriptor the user meant.
bool namesADescriptor(const std::string& path, bool isLink) {
    char resolved[PATH_MAX];
    if (realpath(directoryOf(path).c_str(), resolved) && isPseudoPath(resolved)) return true;
    if (!isLink) return false;
    ssize_t length = readlink(path.c_str(), resolved, sizeof(resolved) - 1);
    return length > 0 && isPseudoPath(std::string(resolved, size_t(length)));
}

int writeAll(int fd, const std::string& bytes) {
    size_t done = 0;
    while (done < bytes.size()) {
        ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return errno;
        if (n == 0) return EIO;  // no progress and no reason: do not spin
        done += size_t(n);
    }
    return 0;
}

}  // namespace

bool namesAStream(const std::string& path) {
    struct stat link, file;
    if (lstat(path.c_str(), &link) != 0) return isPseudoPath(path);
    return namesADescriptor(path, S_ISLNK(link.st_mode)) || stat(path.c_str(), &file) != 0 || !S_ISREG(file.st_mode);
}

namespace {

// Decides between replacing the target and writing in place.
bool plan(const std::string& path, Staged& staged, std::string& error) {
    staged.path = staged.target = path;
    struct stat link, file;
    if (lstat(path.c_str(), &link) != 0) {
        if (errno == ENOENT) return true;  // a new file; a missing directory fails at the temporary
        return fail(path, std::strerror(errno), error);
    }
    bool isLink = S_ISLNK(link.st_mode);
    // A dangling link, a device, a pipe, a terminal, a directory (which then fails with EISDIR).
    if (namesADescriptor(path, isLink) || stat(path.c_str(), &file) != 0 || !S_ISREG(file.st_mode)) {
        staged.inPlace = true;
        return true;
    }
    staged.keptMode = int(file.st_mode & 07777);
    if (isLink) {
        char resolved[PATH_MAX];
        if (!realpath(path.c_str(), resolved)) return fail(path, std::strerror(errno), error);
        staged.target = resolved;
    }
    return true;
}

// Opens a new temporary beside the target; names taken by another writer are skipped. The name is
// registered for removal on a signal before the file exists, so no moment leaves it behind.
int openTemporary(const std::string& target, std::string& name, RemovedOnInterrupt& removal) {
    static std::atomic<unsigned> counter{0};
    std::string base = baseNameOf(target).substr(0, 200);  // room for the suffix within NAME_MAX
    std::string stem = directoryOf(target) + "/." + base + ".tmp-" + std::to_string(getpid()) + "-";
    for (int attempt = 0; attempt < 100; ++attempt) {
        name = stem + std::to_string(counter++);
        removal = RemovedOnInterrupt(name, RemovedOnInterrupt::Kind::File);
        // 0666 less the umask, as for any new file.
        int fd = open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) return fd;
        removal.release();  // not ours: another writer's file, or none was made
        if (errno != EEXIST) return -1;
    }
    errno = EEXIST;
    return -1;
}

// Writes the complete file under a temporary name: every write, the fsync, the size on disk and
// the close checked. On failure nothing is left.
bool writeTemporary(Staged& staged, const std::string& bytes, std::string& error) {
    std::string name;
    int fd = openTemporary(staged.target, name, staged.removal);
    if (fd < 0) return fail(staged.path, std::strerror(errno), error);
    // Best effort: a file system without Unix permissions (vfat) refuses, and the bytes matter more.
    if (staged.keptMode >= 0) (void)fchmod(fd, mode_t(staged.keptMode));
    std::string why;
    struct stat written;
    if (int err = writeAll(fd, bytes)) why = std::strerror(err);
    else if (fsync(fd) != 0) why = std::string("fsync: ") + std::strerror(errno);
    else if (fstat(fd, &written) != 0) why = std::strerror(errno);
    else if (uint64_t(written.st_size) != bytes.size())
        why = std::to_string(written.st_size) + " of " + std::to_string(bytes.size()) + " bytes on disk";
    if (close(fd) != 0 && why.empty()) why = std::string("close: ") + std::strerror(errno);
    if (!why.empty()) {
        unlink(name.c_str());
        staged.removal.release();
        return fail(staged.path, why, error);
    }
    staged.temporary = name;
    return true;
}

bool writeInPlace(const Staged& staged, const std::string& bytes, std::string& error) {
    // O_NONBLOCK: a FIFO that no process reads would block the open forever; it fails with ENXIO.
    int fd = open(staged.path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NONBLOCK, 0666);
    if (fd < 0 && errno == ENXIO) return fail(staged.path, "it is a FIFO (named pipe) that no process reads", error);
    if (fd < 0) return fail(staged.path, std::strerror(errno), error);
    if (fcntl(fd, F_SETFL, 0) != 0) {  // blocking writes from here on: a reader takes its time
        close(fd);
        return fail(staged.path, std::strerror(errno), error);
    }
    std::string why;
    struct stat file;
    if (int err = writeAll(fd, bytes)) why = std::strerror(err);
    else if (fstat(fd, &file) == 0 && S_ISREG(file.st_mode) && fsync(fd) != 0)  // pipes and devices cannot fsync
        why = std::string("fsync: ") + std::strerror(errno);
    if (close(fd) != 0 && why.empty()) why = std::string("close: ") + std::strerror(errno);
    return why.empty() || fail(staged.path, why, error);
}

bool stage(const std::string& path, const std::string& bytes, Staged& staged, std::string& error) {
    if (!plan(path, staged, error)) return false;
    return staged.inPlace || writeTemporary(staged, bytes, error);
}

void discard(Staged& staged) {
    if (!staged.temporary.empty()) unlink(staged.temporary.c_str());
    staged.temporary.clear();
    staged.removal.release();
}

// The rename is what makes the new file appear; syncing the directory makes the rename itself
// durable. A failed directory sync is not reported: the file under the name is complete either way.
bool commit(Staged& staged, const std::string& bytes, std::string& error) {
    if (staged.inPlace) return writeInPlace(staged, bytes, error);
    if (rename(staged.temporary.c_str(), staged.target.c_str()) != 0) {
        int err = errno;
        discard(staged);
        return fail(staged.path, std::strerror(err), error);
    }
    staged.temporary.clear();
    staged.removal.release();
    int directory = open(directoryOf(staged.target).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (directory >= 0) {
        fsync(directory);
        close(directory);
    }
    return true;
}

}  // namespace

bool writeFileWhole(const std::string& path, const std::string& bytes, std::string& error) {
    Staged staged;
    return stage(path, bytes, staged, error) && commit(staged, bytes, error);
}

bool writeFilesWhole(const std::vector<OutputFile>& files, std::vector<std::string>& written, std::string& error) {
    written.clear();
    std::vector<Staged> staged(files.size());
    for (size_t i = 0; i < files.size(); ++i) {
        if (stage(files[i].path, files[i].bytes, staged[i], error)) continue;
        for (size_t j = 0; j < i; ++j) discard(staged[j]);
        return false;
    }
    bool committed = true;
    {
        // A signal between two renames would leave part of the set: it waits until the renames end
        // (not where a target is written in place: a stalled pipe must not make Ctrl-C wait).
        std::optional<InterruptionHeld> holding;
        if (std::none_of(staged.begin(), staged.end(), [](const Staged& s) { return s.inPlace; })) holding.emplace();
        for (size_t i = 0; i < files.size() && committed; ++i) {
            committed = commit(staged[i], files[i].bytes, error);
            if (committed) written.push_back(files[i].path);
            else
                for (size_t j = i + 1; j < files.size(); ++j) discard(staged[j]);
        }
    }
    endForHeldSignal();
    return committed;
}

}  // namespace oasis
