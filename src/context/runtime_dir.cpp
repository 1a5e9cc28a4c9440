// A private XDG_RUNTIME_DIR where the environment has none that is valid (context/runtime_dir.h).
#include "context/runtime_dir.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>

namespace oasis {

bool isValidRuntimeDir(const char* path) {
    struct stat info;
    return path && path[0] == '/' && stat(path, &info) == 0 && S_ISDIR(info.st_mode) && info.st_uid == geteuid() &&
           (info.st_mode & 077) == 0;
}

PrivateRuntimeDir::PrivateRuntimeDir() {
    if (isValidRuntimeDir(std::getenv("XDG_RUNTIME_DIR"))) return;
    const char* root = std::getenv("TMPDIR");
    std::string pattern = std::string(root && *root ? root : "/tmp") + "/oasis-runtime-XXXXXX";
    if (!mkdtemp(pattern.data())) return;  // mkdtemp makes it 0700; without one a driver only warns
    removal_ = RemovedOnInterrupt(pattern, RemovedOnInterrupt::Kind::DirectoryTree);
    path_ = pattern;
    setenv("XDG_RUNTIME_DIR", path_.c_str(), 1);
}

PrivateRuntimeDir::~PrivateRuntimeDir() {
    if (path_.empty()) return;
    removeDirectoryTree(path_);
    removal_.release();
}

}  // namespace oasis
