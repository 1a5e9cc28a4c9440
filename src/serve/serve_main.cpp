// oasis-serve: the web build's page server (docs/web.md). Serves one directory (build-web/ by
// default) on 127.0.0.1 (or --host) with the MIME types a browser insists on (application/wasm
// for WebAssembly streaming compilation), GET and HEAD only. The HTTP itself is cpp-httplib's
// (Debian's libcpp-httplib-dev): request parsing, percent-decoding, a thread pool, read and write
// timeouts. What is oasis's own is which file a target may name (servedFile below): httplib's
// mount point follows symlinks out of the folder, so it is not used.
#include <httplib.h>

#include <arpa/inet.h>
#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "io/printable_text.h"

namespace {

// Silent clients hold a worker only this long (seconds); enough workers that a few of them
// cannot starve the page's own requests (a page load is about ten files).
constexpr time_t kTimeoutSeconds = 5;
constexpr size_t kWorkers = 32;
// The web build's largest file is a few MiB; a bigger one in the folder is not a page's.
constexpr off_t kMaxFileBytes = off_t(512) << 20;

const char* mimeType(const std::string& path) {
    static const struct { const char* suffix; const char* type; } kTypes[] = {
        {".html", "text/html; charset=utf-8"}, {".js", "text/javascript"}, {".mjs", "text/javascript"},
        {".wasm", "application/wasm"}, {".data", "application/octet-stream"}, {".json", "application/json"},
        {".png", "image/png"}, {".css", "text/css"}, {".svg", "image/svg+xml"}};
    for (const auto& entry : kTypes) {
        size_t n = std::strlen(entry.suffix);
        if (path.size() >= n && path.compare(path.size() - n, n, entry.suffix) == 0) return entry.type;
    }
    return "application/octet-stream";
}

bool isDirectory(const std::string& path) {
    struct stat info{};
    return stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
}

// The real path of the regular file the decoded `target` names inside `root` (itself a real
// path), or empty when there is none: a target must start with '/' (else "2/x" would be pasted
// onto the folder's name and reach its sibling "www2"), hold no NUL and no ".." segment, and its
// real path (every symlink resolved) must lie inside root. A directory stands for its index.html
// ("/" for oasis.html, the page).
std::string servedFile(const std::string& root, const std::string& target) {
    if (target.empty() || target[0] != '/' || target.find('\0') != std::string::npos) return {};
    for (size_t at = 0; at != std::string::npos;) {
        size_t end = target.find('/', at + 1);
        if (target.compare(at, end == std::string::npos ? std::string::npos : end - at, "/..") == 0) return {};
        at = end;
    }
    std::string path = root + target;
    if (target == "/") path += "oasis.html";
    else if (isDirectory(path)) path += "/index.html";
    char real[PATH_MAX];
    if (!realpath(path.c_str(), real)) return {};
    std::string resolved = real;
    if (resolved.compare(0, root.size() + 1, root + "/") != 0) return {};
    struct stat info{};
    if (stat(real, &info) != 0 || !S_ISREG(info.st_mode)) return {};
    return resolved;
}

// The file's bytes, read through a descriptor that is checked to be a regular file of bounded
// size (it may have changed since servedFile looked); false when it is not.
bool readRegular(const std::string& path, std::string& body) {
    int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) return false;
    struct stat info{};
    bool ok = fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && info.st_size <= kMaxFileBytes;
    if (ok) body.resize(size_t(info.st_size));
    size_t done = 0;
    while (ok && done < body.size()) {
        ssize_t n = read(fd, &body[done], body.size() - done);
        if (n < 0 && errno == EINTR) continue;
        ok = n > 0;
        if (ok) done += size_t(n);
    }
    close(fd);
    return ok;
}

int usage(const std::string& argument) {
    std::fprintf(stderr, "usage: oasis-serve [--dir build-web] [--port 8080] [--host 127.0.0.1]\n");
    return argument == "--help" ? 0 : 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::string root = "build-web", host = "127.0.0.1";
    int port = 8080;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--port" && i + 1 < argc) {
            // A port is 1..65535, digits only: atoi's 0 for "abc" would listen on a port the
            // kernel picks and print ":0", and 99999 would wrap.
            std::string text = argv[++i];
            bool digits = !text.empty() && text.size() <= 5 && text.find_first_not_of("0123456789") == std::string::npos;
            port = digits ? std::atoi(text.c_str()) : 0;
            if (port < 1 || port > 65535) {
                std::fprintf(stderr, "oasis-serve: --port expects a port in 1..65535, got '%s'\n",
                             oasis::printableText(text).c_str());
                return 2;
            }
        } else if (a == "--dir" && i + 1 < argc) {
            root = argv[++i];
        } else if (a == "--host" && i + 1 < argc) {
            // A numeric address only: a name would be looked up (DNS) before the server listens.
            host = argv[++i];
            unsigned char address[sizeof(in6_addr)];
            if (inet_pton(AF_INET, host.c_str(), address) != 1 && inet_pton(AF_INET6, host.c_str(), address) != 1) {
                std::fprintf(stderr, "oasis-serve: --host expects a numeric address (127.0.0.1, 0.0.0.0, ::1), got '%s'\n",
                             oasis::printableText(host).c_str());
                return 2;
            }
        } else {
            return usage(a);
        }
    }
    char real[PATH_MAX];
    if (access((root + "/oasis.html").c_str(), R_OK) != 0 || !realpath(root.c_str(), real)) {
        std::fprintf(stderr, "oasis-serve: no %s/oasis.html: build it with `bash .ci/setup-web`\n",
                     oasis::printableText(root).c_str());
        return 1;
    }
    const std::string served = real;

    httplib::Server server;
    server.new_task_queue = [] { return new httplib::ThreadPool(kWorkers); };
    server.set_read_timeout(kTimeoutSeconds);
    server.set_write_timeout(kTimeoutSeconds);
    // One request per connection: an idle keep-alive connection would hold a worker as a silent
    // client does; a page load is a few files, each a new connection on loopback.
    server.set_keep_alive_max_count(1);
    server.set_payload_max_length(0);  // GET and HEAD only: a request has no body to read
    server.Get(".*", [&served](const httplib::Request& request, httplib::Response& response) {
        std::string file = servedFile(served, request.path), body;
        if (file.empty() || !readRegular(file, body)) {
            response.status = 404;
            return;
        }
        response.set_header("Cache-Control", "no-cache");
        response.set_content(std::move(body), mimeType(file));
    });
    // Anything but GET or HEAD (httplib answers an unknown method 400 itself).
    auto refuse = [](const httplib::Request&, httplib::Response& response) { response.status = 405; };
    server.Post(".*", refuse).Put(".*", refuse).Delete(".*", refuse).Patch(".*", refuse).Options(".*", refuse);
    // What was refused, one line each; the target is the client's bytes, so never printed raw.
    server.set_logger([](const httplib::Request& request, const httplib::Response& response) {
        if (response.status >= 400)
            std::fprintf(stderr, "oasis-serve: %d %s %s\n", response.status, oasis::printableText(request.method).c_str(),
                         oasis::printableText(request.target).c_str());
    });
    if (!server.bind_to_port(host, port)) {
        std::fprintf(stderr, "oasis-serve: cannot listen on %s:%d: %s\n", oasis::printableText(host).c_str(), port,
                     std::strerror(errno));
        return 1;
    }
    const std::string urlHost = host.find(':') == std::string::npos ? host : "[" + host + "]";  // IPv6 in a URL
    std::printf("oasis-serve: http://%s:%d/oasis.html (serving %s)\n", urlHost.c_str(), port,
                oasis::printableText(root).c_str());
    std::fflush(stdout);
    return server.listen_after_bind() ? 0 : 1;
}
