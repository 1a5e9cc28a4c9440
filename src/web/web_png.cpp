// PNG files for the web build (io/png_text.h's encoding and reading): natively libpng does it
// (io/png_libpng.cpp), but libpng and zlib are emscripten ports that download, which the web
// build does not use (docs/web.md); stb_image and stb_image_write (web_stb.cpp) do it here. The
// page's PNGs stay in its own file system, so they carry no text chunks and none are read.
#include "io/png_text.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstring>

namespace oasis {
namespace {

bool sizeAllowed(int width, int height, std::string& error, uint32_t maxSide) {
    uint32_t limit = std::min(maxSide, kMaxPngSide);
    if (uint32_t(width) > limit || uint32_t(height) > limit ||
        uint64_t(width) * uint64_t(height) * 4 > kMaxPngDecodedBytes) {
        error = "its header says " + std::to_string(width) + "x" + std::to_string(height) +
                " pixels; oasis reads at most " + std::to_string(limit) + " a side";
        return false;
    }
    return true;
}

bool isPng(const std::string& png, std::string& error) {
    if (png.size() >= 8 && png.compare(0, 8, "\x89PNG\r\n\x1a\n", 8) == 0) return true;
    error = "not a PNG file";
    return false;
}

}  // namespace

bool encodePngBytes(const uint8_t* rgba, int width, int height, const std::vector<PngText>&, std::string& png,
                    std::string& error) {
    png.clear();
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
    };
    if (width < 1 || height < 1 || !stbi_write_png_to_func(append, &png, width, height, 4, rgba, width * 4) || png.empty()) {
        error = "stb_image_write failed (" + std::to_string(width) + "x" + std::to_string(height) + ")";
        return false;
    }
    return true;
}

bool readPngHeader(const std::string& png, PngHeader& header, std::string& error, uint32_t maxSide) {
    header = PngHeader{};
    int width = 0, height = 0, channels = 0;
    if (!isPng(png, error)) return false;
    if (!stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(png.data()), int(png.size()), &width, &height, &channels)) {
        error = std::string("not a readable PNG (") + stbi_failure_reason() + ")";
        return false;
    }
    header.width = uint32_t(width);
    header.height = uint32_t(height);
    return sizeAllowed(width, height, error, maxSide);
}

PngTexts readPngTexts(const std::string&) {
    PngTexts none;
    none.ignored.push_back("the web build reads no PNG text chunks");
    return none;
}

bool decodePngBytes(const std::string& png, std::vector<uint8_t>& rgba, uint32_t& width, uint32_t& height,
                    std::string& error, uint32_t maxSide) {
    PngHeader header;
    if (!readPngHeader(png, header, error, maxSide)) return false;
    int w = 0, h = 0, channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(png.data()), int(png.size()), &w, &h,
                                            &channels, 4);
    if (!pixels) {
        error = std::string("not a readable PNG (") + stbi_failure_reason() + ")";
        return false;
    }
    width = uint32_t(w);
    height = uint32_t(h);
    rgba.assign(pixels, pixels + size_t(w) * size_t(h) * 4);
    stbi_image_free(pixels);
    return true;
}

}  // namespace oasis
