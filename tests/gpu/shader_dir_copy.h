// A throw-away copy of the shader directory, for GPU tests that edit shaders: a broken file to
// reload (bad_input_test.cpp), or a reference variant put back to compare against (shadows_test.cpp).
#pragma once
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace oasis::gputest {

inline std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

inline void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::trunc);
    out << text;
}

// A copy of the real shader directory in a fresh temporary directory, removed afterwards.
struct ShaderDirCopy {
    std::filesystem::path root;
    explicit ShaderDirCopy(const std::string& source) {
        root = std::filesystem::temp_directory_path() / ("oasis-gpu-shaders-" + std::to_string(::getpid()));
        std::filesystem::remove_all(root);
        std::filesystem::copy(source, root, std::filesystem::copy_options::recursive);
    }
    ~ShaderDirCopy() {
        std::error_code ignored;
        std::filesystem::remove_all(root, ignored);
    }
};

}  // namespace oasis::gputest
