// Every file oasis writes goes through here, so that an output is written whole or not at all:
// the bytes go to a temporary name beside the target, every step is checked, then it is renamed.
#pragma once
#include <string>
#include <vector>

namespace oasis {

struct OutputFile {
    std::string path;
    std::string bytes;  // the whole file, already encoded (binary is fine)
};

// Writes `bytes` to `path` whole: to ".NAME.tmp-PID-N" in the target's directory, each write, the
// fsync, the size and the close checked, then renamed over `path`. On failure the temporary is
// removed, `path` is as it was, and `error` says "cannot write PATH: REASON". A path that exists
// and is not a regular file (/dev/full, a pipe, a terminal) or that lies in /dev or /proc
// (/dev/stdout) cannot be replaced: it is written in place, every write and the close checked.
bool writeFileWhole(const std::string& path, const std::string& bytes, std::string& error);

// Whether `path` names a stream or device rather than a file (it exists and is not a regular file,
// or it lies in /dev or /proc): written in place, and its name carries no file format.
bool namesAStream(const std::string& path);

// Writes a set of files that belong together (one run's images or reports): every file is first
// written to its temporary; only when all are complete are they renamed, so a failure leaves the
// targets as they were (no new file, and no mix of this run's files with an earlier run's). The
// paths renamed before a failure (only a failing rename can leave any) are in `written`, in order;
// on success `written` holds every path.
bool writeFilesWhole(const std::vector<OutputFile>& files, std::vector<std::string>& written, std::string& error);

}  // namespace oasis
