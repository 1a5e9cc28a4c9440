// Image output and comparison.
#include "render/image.h"

#include <stb_image_write.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace oasis {

void Image::flipRows() {
    size_t rowBytes = size_t(width) * 4;
    std::vector<uint8_t> row(rowBytes);
    for (int y = 0; y < height / 2; ++y) {
        uint8_t* top = &rgba[size_t(y) * rowBytes];
        uint8_t* bottom = &rgba[size_t(height - 1 - y) * rowBytes];
        std::memcpy(row.data(), top, rowBytes);
        std::memcpy(top, bottom, rowBytes);
        std::memcpy(bottom, row.data(), rowBytes);
    }
}

bool writePng(const std::string& path, const Image& image, std::string& error) {
    errno = 0;
    if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4)) {
        error = "cannot write " + path + (errno ? std::string(": ") + std::strerror(errno) : std::string());
        return false;
    }
    return true;
}

ImageDifference compareImages(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("images differ in size");
    double sumSquares = 0.0;
    ImageDifference result;
    size_t pixels = size_t(a.width) * size_t(a.height);
    for (size_t i = 0; i < pixels; ++i) {
        for (int c = 0; c < 3; ++c) {
            int d = int(a.rgba[i * 4 + c]) - int(b.rgba[i * 4 + c]);
            sumSquares += double(d) * double(d);
            result.maxAbs = std::max(result.maxAbs, std::abs(d));
        }
    }
    double mse = pixels ? sumSquares / double(pixels * 3) : 0.0;
    result.rmse = std::sqrt(mse);
    result.psnrDb = mse > 0.0 ? std::min(kPsnrIdentical, 10.0 * std::log10(255.0 * 255.0 / mse)) : kPsnrIdentical;
    return result;
}

Image differenceHeatmap(const Image& a, const Image& b, int fullScale) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("images differ in size");
    Image heat(a.width, a.height);
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            int d = 0;
            for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])));
            float t = std::min(1.0f, float(d) / float(fullScale));
            uint8_t* out = heat.pixel(x, y);
            out[0] = uint8_t(255.0f * std::min(1.0f, t * 3.0f));
            out[1] = uint8_t(255.0f * std::clamp(t * 3.0f - 1.0f, 0.0f, 1.0f));
            out[2] = uint8_t(255.0f * std::clamp(t * 3.0f - 2.0f, 0.0f, 1.0f));
            out[3] = 255;
        }
    }
    return heat;
}

}  // namespace oasis
