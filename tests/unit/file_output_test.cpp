// Covers src/io/file_output.h: a file is written whole or not at all. Real failures, no mocks:
// a file-size limit (RLIMIT_FSIZE, set in a forked child so it cannot touch the test runner) makes
// the Nth byte's write fail with EFBIG; /dev/full fails with ENOSPC.
#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "io/file_output.h"

namespace oasis {
namespace {

namespace fs = std::filesystem;

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void putFile(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// Bytes that differ at every offset, so a truncated or shifted file cannot compare equal.
std::string varied(size_t size, int seed) {
    std::string bytes(size, '\0');
    for (size_t i = 0; i < size; ++i) bytes[i] = char((i * 131 + size_t(seed) * 17 + (i >> 8)) & 255);
    return bytes;
}

std::set<std::string> namesIn(const std::string& dir) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
    return names;
}

// Runs `body` in a child whose files may grow to `limit` bytes (SIGXFSZ ignored, so a write past
// the limit fails with EFBIG instead of killing it); returns the child's exit status.
int withFileSizeLimit(rlim_t limit, const std::function<int()>& body) {
    pid_t child = fork();
    if (child == 0) {
        signal(SIGXFSZ, SIG_IGN);
        struct rlimit cap = {limit, limit};
        if (setrlimit(RLIMIT_FSIZE, &cap) != 0) _exit(90);
        _exit(body());
    }
    int status = 0;
    waitpid(child, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 100 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

class FileOutput : public ::testing::Test {
protected:
    void SetUp() override {
        char pattern[] = "/tmp/oasis-file-output-XXXXXX";
        ASSERT_NE(mkdtemp(pattern), nullptr);
        dir = pattern;
    }
    void TearDown() override {
        if (!dir.empty()) fs::remove_all(dir);
    }
    std::string dir;
};

TEST_F(FileOutput, ASuccessfulWriteLeavesExactlyTheTarget) {
    std::string bytes = varied(100000, 1), error;
    ASSERT_TRUE(writeFileWhole(dir + "/out.bin", bytes, error)) << error;
    EXPECT_EQ(namesIn(dir), std::set<std::string>{"out.bin"});
    EXPECT_EQ(readFile(dir + "/out.bin"), bytes);
    ASSERT_TRUE(writeFileWhole(dir + "/empty.txt", "", error)) << error;
    EXPECT_EQ(fs::file_size(dir + "/empty.txt"), 0u);
    EXPECT_EQ(namesIn(dir), (std::set<std::string>{"out.bin", "empty.txt"}));
}

TEST_F(FileOutput, ReplacingKeepsThePermissionsAndALinkStaysALink) {
    std::string real = dir + "/real.txt", link = dir + "/link.txt", error;
    putFile(real, "old contents, longer than the new ones");
    ASSERT_EQ(chmod(real.c_str(), 0640), 0);
    ASSERT_EQ(symlink("real.txt", link.c_str()), 0);
    ASSERT_TRUE(writeFileWhole(link, "new", error)) << error;
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(readFile(real), "new");
    EXPECT_EQ(fs::status(real).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    EXPECT_EQ(namesIn(dir), (std::set<std::string>{"real.txt", "link.txt"}));
}

// The limit falls at every interesting byte: before the first, after one, inside, one short.
TEST_F(FileOutput, AWriteThatFailsAtByteNLeavesTheOldFileAndNoTemporary) {
    const std::string target = dir + "/report.json", old = "the previous run's complete file\n";
    const std::string bytes = varied(20000, 2);
    for (rlim_t limit : {rlim_t(0), rlim_t(1), rlim_t(4096), rlim_t(12345), rlim_t(bytes.size() - 1)}) {
        putFile(target, old);
        int status = withFileSizeLimit(limit, [&] {
            std::string error;
            if (writeFileWhole(target, bytes, error)) return 1;
            return error == "cannot write " + target + ": " + std::strerror(EFBIG) ? 0 : 2;
        });
        EXPECT_EQ(status, 0) << "limit " << limit << " (1: reported success, 2: wrong message)";
        EXPECT_EQ(readFile(target), old) << "limit " << limit;
        EXPECT_EQ(namesIn(dir), std::set<std::string>{"report.json"}) << "limit " << limit;
    }
    // At exactly the file's size it fits.
    int status = withFileSizeLimit(bytes.size(), [&] {
        std::string error;
        return writeFileWhole(target, bytes, error) ? 0 : 1;
    });
    EXPECT_EQ(status, 0);
    EXPECT_EQ(readFile(target), bytes);
    EXPECT_EQ(namesIn(dir), std::set<std::string>{"report.json"});
}

// A set (one run's files) is renamed only when every file is complete: the third file failing
// leaves the earlier run's three files as they were, none of this run's.
TEST_F(FileOutput, ASetThatFailsOnItsThirdFileReplacesNone) {
    std::vector<OutputFile> files = {{dir + "/a.png", varied(800, 3)},
                                     {dir + "/b.png", varied(900, 4)},
                                     {dir + "/c.png", varied(5000, 5)}};
    for (const OutputFile& file : files) putFile(file.path, "old " + file.path);
    int status = withFileSizeLimit(1000, [&] {
        std::vector<std::string> written;
        std::string error;
        if (writeFilesWhole(files, written, error)) return 1;
        if (!written.empty()) return 2;
        return error == "cannot write " + dir + "/c.png: " + std::strerror(EFBIG) ? 0 : 3;
    });
    EXPECT_EQ(status, 0) << "1: reported success, 2: reported files written, 3: wrong message";
    for (const OutputFile& file : files) EXPECT_EQ(readFile(file.path), "old " + file.path);
    EXPECT_EQ(namesIn(dir), (std::set<std::string>{"a.png", "b.png", "c.png"}));

    std::vector<std::string> written;
    std::string error;
    ASSERT_TRUE(writeFilesWhole(files, written, error)) << error;
    EXPECT_EQ(written, (std::vector<std::string>{files[0].path, files[1].path, files[2].path}));
    for (const OutputFile& file : files) EXPECT_EQ(readFile(file.path), file.bytes);
    EXPECT_EQ(namesIn(dir), (std::set<std::string>{"a.png", "b.png", "c.png"}));
}

TEST_F(FileOutput, DevFullFailsWithNoSpaceNamingIt) {
    if (access("/dev/full", W_OK) != 0) GTEST_SKIP() << "no writable /dev/full on this machine";
    std::string error;
    EXPECT_FALSE(writeFileWhole("/dev/full", varied(10, 6), error));
    EXPECT_EQ(error, std::string("cannot write /dev/full: ") + std::strerror(ENOSPC));
}

// /dev/fd/N names a descriptor: it is written in place (a rename would replace the link), here a
// pipe whose other end reads back the bytes.
TEST_F(FileOutput, ADescriptorPathIsWrittenInPlace) {
    int ends[2];
    ASSERT_EQ(pipe(ends), 0);
    std::string bytes = varied(3000, 7), error;
    bool ok = writeFileWhole("/dev/fd/" + std::to_string(ends[1]), bytes, error);
    close(ends[1]);
    std::string got(bytes.size() + 10, '\0');
    ssize_t total = 0, n = 0;
    while ((n = read(ends[0], &got[size_t(total)], got.size() - size_t(total))) > 0) total += n;
    close(ends[0]);
    ASSERT_TRUE(ok) << error;
    EXPECT_EQ(got.substr(0, size_t(total)), bytes);
}

TEST_F(FileOutput, MissingDirectoriesAndDirectoriesFailNamingThePath) {
    std::string error;
    EXPECT_FALSE(writeFileWhole(dir + "/missing/x.png", "x", error));
    EXPECT_EQ(error, "cannot write " + dir + "/missing/x.png: " + std::strerror(ENOENT));
    fs::create_directory(dir + "/sub");
    EXPECT_FALSE(writeFileWhole(dir + "/sub", "x", error));
    EXPECT_EQ(error, "cannot write " + dir + "/sub: " + std::strerror(EISDIR));
    EXPECT_TRUE(fs::is_directory(dir + "/sub"));
    EXPECT_EQ(namesIn(dir), std::set<std::string>{"sub"});
}

}  // namespace
}  // namespace oasis
