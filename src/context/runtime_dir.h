// A private XDG_RUNTIME_DIR for drivers that look one up (zink over lavapipe), so that none prints
// "error: XDG_RUNTIME_DIR is invalid or not set in the environment." (issue 31, defect 9).
#pragma once
#include <string>

#include "io/interruption.h"

namespace oasis {

// Whether `path` is a usable runtime directory as the XDG spec asks: absolute, a directory, owned
// by this user, with no access for anyone else (0700).
bool isValidRuntimeDir(const char* path);

// While it exists: where XDG_RUNTIME_DIR is unset or invalid, the variable names a fresh 0700
// directory under TMPDIR (or /tmp), removed (with anything a driver left in it) when this ends or
// a signal ends oasis. A valid XDG_RUNTIME_DIR is left alone. Created at the start of main(),
// before any context: libwayland-client, which Mesa's zink loads through lavapipe's WSI, reads the
// variable when it connects, and the variable has to be set before that.
class PrivateRuntimeDir {
public:
    PrivateRuntimeDir();
    ~PrivateRuntimeDir();
    PrivateRuntimeDir(const PrivateRuntimeDir&) = delete;
    PrivateRuntimeDir& operator=(const PrivateRuntimeDir&) = delete;
    const std::string& path() const { return path_; }  // empty: the environment's own was kept

private:
    std::string path_;
    RemovedOnInterrupt removal_;
};

}  // namespace oasis
