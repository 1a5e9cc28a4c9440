// Checked file input (io/file_input.h): open without blocking, fstat the open file, then read.
#include "io/file_input.h"
#include "io/printable_text.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace oasis {
namespace {

bool fail(const std::string& path, const std::string& why, std::string& error) {
    error = "cannot read " + printableText(path) + ": " + why;
    return false;
}

// What a non-regular file is, in a user's words.
const char* kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "it is a directory";
    if (S_ISFIFO(mode)) return "it is a FIFO (named pipe), which could block: only regular files are read";
    if (S_ISSOCK(mode)) return "it is a socket: only regular files are read";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "it is a device: only regular files are read";
    return "it is not a regular file";
}

}  // namespace

int openRegularFile(const std::string& path, size_t maxBytes, std::string& error) {
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer before the check.
    int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        fail(path, std::strerror(errno), error);
        return -1;
    }
    struct stat file;
    std::string why;
    // The open file itself is checked, so a name swapped after a check cannot slip through.
    if (fstat(fd, &file) != 0) why = std::strerror(errno);
    else if (!S_ISREG(file.st_mode)) why = kindOf(file.st_mode);
    else if (uint64_t(file.st_size) > maxBytes)
        why = "it is " + std::to_string(file.st_size) + " bytes, more than the " + std::to_string(maxBytes) +
              " bytes read for such a file";
    else if (fcntl(fd, F_SETFL, 0) != 0)  // ordinary blocking reads from here on
        why = std::strerror(errno);
    if (why.empty()) return fd;
    close(fd);
    fail(path, why, error);
    return -1;
}

bool readUpTo(int fd, size_t count, std::string& bytes, const std::string& path, std::string& error) {
    // In slices, so that a limit far above the file's size costs no memory.
    char slice[65536];
    while (count > 0) {
        ssize_t n = read(fd, slice, count < sizeof(slice) ? count : sizeof(slice));
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return fail(path, std::strerror(errno), error);
        if (n == 0) break;
        bytes.append(slice, size_t(n));
        count -= size_t(n);
    }
    return true;
}

bool readRegularFile(const std::string& path, size_t maxBytes, std::string& bytes, std::string& error) {
    bytes.clear();
    int fd = openRegularFile(path, maxBytes, error);
    if (fd < 0) return false;
    // One byte past the limit tells a file that grew after the check.
    bool ok = readUpTo(fd, maxBytes + 1, bytes, path, error);
    close(fd);
    if (ok && bytes.size() > maxBytes)
        return fail(path, "it grew past the " + std::to_string(maxBytes) + " bytes read for such a file", error);
    return ok;
}

}  // namespace oasis
