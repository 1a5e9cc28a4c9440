// Image output (PNG encoded in memory through libpng, io/png_text.h, written whole), input and comparison.
#include "render/image.h"

#include "io/file_input.h"
#include "io/file_output.h"
#include "io/printable_text.h"


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

bool encodePng(const Image& image, std::string& png, const std::vector<PngText>& texts, std::string* why) {
    std::string error;
    bool encoded = encodePngBytes(image.rgba.data(), image.width, image.height, texts, png, error);
    if (!encoded && why) *why = error;
    return encoded;
}

bool writePng(const std::string& path, const Image& image, std::string& error, const std::vector<PngText>& texts) {
    std::string png, why;
    if (!encodePng(image, png, texts, &why)) {
        error = "cannot write " + printableText(path) + ": PNG encoding failed (" + std::to_string(image.width) + "x" +
                std::to_string(image.height) + ": " + why + ")";
        return false;
    }
    return writeFileWhole(path, png, error);
}

namespace {

// What a PNG file may be before oasis looks inside: a regular file of bounded size.
constexpr size_t kMaxPngFileBytes = size_t(256) << 20;

}  // namespace

bool readPngFile(const std::string& path, std::string& bytes, PngHeader& header, std::string& error,
                 uint32_t maxSide) {
    if (!readRegularFile(path, kMaxPngFileBytes, bytes, error)) return false;
    if (!readPngHeader(bytes, header, error, maxSide)) {
        error = "cannot read " + printableText(path) + ": " + error;
        return false;
    }
    return true;
}

bool decodePng(const std::string& path, const std::string& bytes, Image& image, std::string& error, uint32_t maxSide) {
    std::vector<uint8_t> rgba;
    uint32_t width = 0, height = 0;
    if (!decodePngBytes(bytes, rgba, width, height, error, maxSide)) {
        error = "cannot read " + printableText(path) + ": " + error;
        return false;
    }
    image.width = int(width);
    image.height = int(height);
    image.rgba = std::move(rgba);
    return true;
}

bool readPng(const std::string& path, Image& image, std::string& error, PngTexts* texts, uint32_t maxSide) {
    std::string bytes;
    PngHeader header;
    if (!readPngFile(path, bytes, header, error, maxSide) || !decodePng(path, bytes, image, error, maxSide)) return false;
    if (texts) *texts = std::move(header.texts);
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

Image stackImages(const Image& top, const Image& bottom) {
    if (bottom.height == 0) return top;
    if (top.width != bottom.width) throw std::invalid_argument("stacked images differ in width");
    Image stacked(top.width, top.height + bottom.height);
    std::copy(top.rgba.begin(), top.rgba.end(), stacked.rgba.begin());
    std::copy(bottom.rgba.begin(), bottom.rgba.end(), stacked.rgba.begin() + std::ptrdiff_t(top.rgba.size()));
    return stacked;
}

void differenceHeatColour(float t, uint8_t rgb[3]) {
    // Any non-zero difference at least as bright as 3/16 of the scale (red 143): one level at the
    // default full scale of 16 was red 47, five such pixels invisible in difference.png (issue 31,
    // defect 6). The counts of differing pixels say how many are that small.
    if (t > 0.0f) t = std::max(t, kMinVisibleHeat);
    rgb[0] = uint8_t(255.0f * std::clamp(t * 3.0f, 0.0f, 1.0f));
    rgb[1] = uint8_t(255.0f * std::clamp(t * 3.0f - 1.0f, 0.0f, 1.0f));
    rgb[2] = uint8_t(255.0f * std::clamp(t * 3.0f - 2.0f, 0.0f, 1.0f));
}

DifferingPixels countDifferingPixels(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height) throw std::invalid_argument("images differ in size");
    DifferingPixels counts;
    counts.pixels = long(a.width) * long(a.height);
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            int d = 0;
            for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])));
            for (size_t i = 0; i < DifferingPixels::kLevels.size(); ++i) counts.over[i] += d > DifferingPixels::kLevels[i];
        }
    return counts;
}

std::string DifferingPixels::describe() const {
    std::string text = "pixels differing by more than";
    for (size_t i = 0; i < kLevels.size(); ++i)
        text += (i ? ", " : " ") + std::to_string(kLevels[i]) + ": " + std::to_string(over[i]);
    return text + " levels (of " + std::to_string(pixels) + ")";
}

std::string DifferingPixels::json() const {
    std::string text = "{";
    for (size_t i = 0; i < kLevels.size(); ++i)
        text += (i ? ", \"" : "\"") + std::to_string(kLevels[i]) + "\": " + std::to_string(over[i]);
    return text + "}";
}

Image differenceHeatmap(const Image& a, const Image& b, int fullScale) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("images differ in size");
    Image heat(a.width, a.height);
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            int d = 0;
            for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])));
            uint8_t* out = heat.pixel(x, y);
            differenceHeatColour(std::min(1.0f, float(d) / float(fullScale)), out);
            out[3] = 255;
        }
    }
    return heat;
}

}  // namespace oasis

namespace oasis {
namespace {

std::vector<double> luminance(const Image& image) {
    std::vector<double> y(size_t(image.width) * size_t(image.height));
    for (size_t i = 0; i < y.size(); ++i) {
        const uint8_t* p = &image.rgba[i * 4];
        y[i] = 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
    }
    return y;
}

// Separable Gaussian filter over the windows that fit wholly in the image ("valid" positions);
// the result is (width - size + 1) x (height - size + 1).
std::vector<double> gaussianValid(const std::vector<double>& in, int width, int height,
                                  const std::vector<double>& kernel) {
    int size = int(kernel.size());
    int outW = width - size + 1, outH = height - size + 1;
    std::vector<double> rows(size_t(outW) * size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < outW; ++x) {
            double sum = 0.0;
            for (int k = 0; k < size; ++k) sum += kernel[k] * in[size_t(y) * width + x + k];
            rows[size_t(y) * outW + x] = sum;
        }
    std::vector<double> out(size_t(outW) * size_t(outH));
    for (int y = 0; y < outH; ++y)
        for (int x = 0; x < outW; ++x) {
            double sum = 0.0;
            for (int k = 0; k < size; ++k) sum += kernel[k] * rows[size_t(y + k) * outW + x];
            out[size_t(y) * outW + x] = sum;
        }
    return out;
}

}  // namespace

double ssim(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("ssim: images differ in size");
    if (a.width < 1 || a.height < 1) throw std::invalid_argument("ssim: empty images");
    const double c1 = (0.01 * 255.0) * (0.01 * 255.0), c2 = (0.03 * 255.0) * (0.03 * 255.0);
    // 11 taps, sigma 1.5; a smaller image gets a window as large as it (one window, clipped).
    int size = std::min({11, a.width, a.height});
    std::vector<double> kernel(size_t(size), 0.0);
    double total = 0.0;
    for (int k = 0; k < size; ++k) {
        double d = k - (size - 1) * 0.5;
        total += kernel[k] = std::exp(-d * d / (2.0 * 1.5 * 1.5));
    }
    for (double& k : kernel) k /= total;
    std::vector<double> x = luminance(a), y = luminance(b);
    std::vector<double> xx(x.size()), yy(x.size()), xy(x.size());
    for (size_t i = 0; i < x.size(); ++i) {
        xx[i] = x[i] * x[i];
        yy[i] = y[i] * y[i];
        xy[i] = x[i] * y[i];
    }
    int w = a.width, h = a.height;
    std::vector<double> mx = gaussianValid(x, w, h, kernel), my = gaussianValid(y, w, h, kernel);
    std::vector<double> sxx = gaussianValid(xx, w, h, kernel), syy = gaussianValid(yy, w, h, kernel);
    std::vector<double> sxy = gaussianValid(xy, w, h, kernel);
    double sum = 0.0;
    for (size_t i = 0; i < mx.size(); ++i) {
        double varX = sxx[i] - mx[i] * mx[i], varY = syy[i] - my[i] * my[i], cov = sxy[i] - mx[i] * my[i];
        sum += ((2.0 * mx[i] * my[i] + c1) * (2.0 * cov + c2)) /
               ((mx[i] * mx[i] + my[i] * my[i] + c1) * (varX + varY + c2));
    }
    return sum / double(mx.size());
}

}  // namespace oasis
