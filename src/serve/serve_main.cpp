// oasis-serve: the web build's page server (docs/web.md). Serves one directory (build-web/ by
// default) on 127.0.0.1 with the MIME types a browser insists on (application/wasm for
// WebAssembly streaming compilation), GET and HEAD only, one request per connection.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

namespace {
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

void sendAll(int fd, const std::string& data) {
    size_t sent = 0;
    while (sent < data.size()) {
        ssize_t n = send(fd, data.data() + sent, data.size() - sent, MSG_NOSIGNAL);
        if (n <= 0) return;
        sent += size_t(n);
    }
}

void respond(int fd, const std::string& root) {
    char buffer[8192];
    ssize_t n = recv(fd, buffer, sizeof(buffer) - 1, 0);
    if (n <= 0) return;
    buffer[n] = '\0';
    std::istringstream request(buffer);
    std::string method, target;
    request >> method >> target;
    std::string path = target.substr(0, target.find('?'));
    if (path == "/") path = "/oasis.html";
    // Only plain names inside the served directory: no "..", no encoded characters.
    bool safe = (method == "GET" || method == "HEAD") && path.find("..") == std::string::npos &&
                path.find('%') == std::string::npos;
    std::ifstream file(root + path, std::ios::binary);
    if (!safe || !file) {
        sendAll(fd, "HTTP/1.1 404 Not Found\r\nContent-Length: 0\r\nConnection: close\r\n\r\n");
        std::fprintf(stderr, "oasis-serve: 404 %s %s\n", method.c_str(), target.c_str());
        return;
    }
    std::string body((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    std::string head = "HTTP/1.1 200 OK\r\nContent-Type: " + std::string(mimeType(path)) +
                       "\r\nContent-Length: " + std::to_string(body.size()) +
                       "\r\nCache-Control: no-cache\r\nConnection: close\r\n\r\n";
    sendAll(fd, method == "HEAD" ? head : head + body);
}
}  // namespace

int main(int argc, char** argv) {
    std::string root = "build-web";
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
                std::fprintf(stderr, "oasis-serve: --port expects a port in 1..65535, got '%s'\n", text.c_str());
                return 2;
            }
        }
        else if (a == "--dir" && i + 1 < argc) root = argv[++i];
        else {
            std::fprintf(stderr, "usage: oasis-serve [--dir build-web] [--port 8080]\n");
            return a == "--help" ? 0 : 2;
        }
    }
    if (access((root + "/oasis.html").c_str(), R_OK) != 0) {
        std::fprintf(stderr, "oasis-serve: no %s/oasis.html: build it with `bash .ci/setup-web`\n", root.c_str());
        return 1;
    }
    int server = socket(AF_INET, SOCK_STREAM, 0);
    int yes = 1;
    setsockopt(server, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(uint16_t(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);  // this machine only
    if (bind(server, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0 || listen(server, 16) != 0) {
        std::fprintf(stderr, "oasis-serve: cannot listen on 127.0.0.1:%d: %s\n", port, std::strerror(errno));
        return 1;
    }
    std::printf("oasis-serve: http://127.0.0.1:%d/oasis.html (serving %s)\n", port, root.c_str());
    std::fflush(stdout);
    signal(SIGPIPE, SIG_IGN);
    for (;;) {
        int client = accept(server, nullptr, nullptr);
        if (client < 0) continue;
        respond(client, root);
        close(client);
    }
}
