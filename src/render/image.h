// 8-bit RGBA images (top row first): PNG output and input and the comparisons oasis reports between
// frames (PSNR, RMSE and max absolute difference over RGB, and a difference heat map).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "io/png_text.h"

namespace oasis {

struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgba(size_t(w) * size_t(h) * 4, 0) {}
    const uint8_t* pixel(int x, int y) const { return &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
    uint8_t* pixel(int x, int y) { return &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
    void flipRows();
};

// The PNG file's bytes, encoded in memory by libpng, with `texts` as iTXt chunks before the image
// data (io/png_text.h); false, with `why` if given, if the encoder fails (no memory, an empty
// image) or a text cannot be a chunk (a bad keyword, over kMaxPngTextBytes).
bool encodePng(const Image& image, std::string& png, const std::vector<PngText>& texts = {}, std::string* why = nullptr);

// Writes a PNG (with `texts`, as encodePng) whole or not at all (io/file_output.h); on failure
// returns false and `error` says "cannot write PATH: REASON".
bool writePng(const std::string& path, const Image& image, std::string& error, const std::vector<PngText>& texts = {});

// Reading is two steps, so that a caller judges what a file claims before paying for its pixels:
// readPngFile reads the file (io/file_input.h: a regular file of at most 256 MiB) and its
// header and text chunks (io/png_text.h: at most `maxSide` pixels a side, 4096 unless the
// caller was given --allow-large); decodePng then decodes its pixels (any bit depth or channel
// count, to 8-bit RGBA, alpha 255 where it has none). Each is false with `error` saying "cannot
// read PATH: REASON" (the path escaped, io/printable_text.h) when the file is missing, not a
// regular file, not a PNG, cut, fails a CRC or is over the limits.
bool readPngFile(const std::string& path, std::string& bytes, PngHeader& header, std::string& error,
                 uint32_t maxSide = kDefaultMaxPngSide);
bool decodePng(const std::string& path, const std::string& bytes, Image& image, std::string& error,
               uint32_t maxSide = kDefaultMaxPngSide);
// Both steps; `texts`, if given, gets the file's text chunks.
bool readPng(const std::string& path, Image& image, std::string& error, PngTexts* texts = nullptr,
             uint32_t maxSide = kDefaultMaxPngSide);

// PSNR is capped at kPsnrIdentical (identical images have infinite PSNR).
constexpr double kPsnrIdentical = 100.0;
struct ImageDifference {
    double psnrDb = kPsnrIdentical;
    double rmse = 0.0;
    int maxAbs = 0;
};
// Over the RGB channels of same-sized images. Throws std::invalid_argument if sizes differ.
ImageDifference compareImages(const Image& a, const Image& b);

// Mean structural similarity (Wang et al. 2004) of the luminance (Rec. 601: 0.299 R + 0.587 G +
// 0.114 B, 0..255) of same-sized images: 11x11 Gaussian windows (sigma 1.5), C1 = (0.01*255)^2,
// C2 = (0.03*255)^2, averaged over every window that lies wholly inside the image (images smaller
// than a window use one window clipped to the image). 1 for identical images, symmetric in a and b.
// Throws std::invalid_argument if sizes differ or the images are empty.
double ssim(const Image& a, const Image& b);

// Per pixel max channel difference on a black-red-yellow-white scale that saturates at `fullScale`.
// Throws std::invalid_argument if sizes differ.
Image differenceHeatmap(const Image& a, const Image& b, int fullScale = 16);
// The heat map's colour at t = difference / fullScale in 0..1 (its legend draws the same scale);
// any t > 0 at least kMinVisibleHeat, so that a one-level difference shows.
constexpr float kMinVisibleHeat = 3.0f / 16.0f;
void differenceHeatColour(float t, uint8_t rgb[3]);

// How many pixels differ by more than 0, 1, 4 and 16 levels (the largest RGB channel difference):
// the heat map shows where, these say how many. Throws std::invalid_argument if sizes differ.
struct DifferingPixels {
    static constexpr std::array<int, 4> kLevels = {0, 1, 4, 16};
    std::array<long, 4> over{};
    long pixels = 0;
    std::string describe() const;  // "pixels differing by more than 0: N, 1: N, 4: N, 16: N levels (of P)"
    std::string json() const;      // {"0": N, "1": N, "4": N, "16": N}
};
DifferingPixels countDifferingPixels(const Image& a, const Image& b);
// `bottom` under `top` (the same width): a frame and its legend strip in one image; an empty
// `bottom` leaves `top` as it is.
Image stackImages(const Image& top, const Image& bottom);

}  // namespace oasis
