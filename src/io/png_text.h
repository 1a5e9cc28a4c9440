// PNG files: encoding with text chunks (iTXt, uncompressed UTF-8) and reading in two steps, the
// header and text chunks first (what the file claims to be, its size and oasis's provenance,
// commands/provenance.h), the pixels only after the caller has judged those. Natively libpng does
// it (Debian's libpng-dev, io/png_libpng.cpp): it checks every chunk's CRC and, with the limits
// set there, refuses a file whose header or chunks would need more memory than oasis allows before
// it allocates any. The web build's own is src/web/web_png.cpp.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/printable_text.h"  // validUtf8: iTXt holds UTF-8 only

namespace oasis {

struct PngText {
    std::string keyword;  // 1..79 bytes of printable Latin-1, no leading, trailing or double spaces
    std::string text;     // UTF-8 (iTXt); a tEXt chunk's Latin-1 is converted to UTF-8 when read
};

// What a reader keeps: at most this many text chunks, each of at most this many bytes of data.
constexpr size_t kMaxPngTexts = 64;
constexpr size_t kMaxPngTextBytes = size_t(64) << 10;

// Whether `keyword` is one PNG allows (the rule above); `why` says what is wrong otherwise.
bool validPngKeyword(const std::string& keyword, std::string* why = nullptr);

// The PNG file's bytes for `width` x `height` 8-bit RGBA pixels (top row first), with one iTXt chunk
// per text before the image data. False with `error` when a text's keyword is not valid, a text
// exceeds kMaxPngTextBytes or libpng fails.
bool encodePngBytes(const uint8_t* rgba, int width, int height, const std::vector<PngText>& texts, std::string& png,
                    std::string& error);

// The text chunks of PNG bytes, in file order, and what was left out and why (a chunk that fails
// its CRC, a compressed zTXt, past kMaxPngTexts, a repeated keyword: the first is kept). A keyword
// that appears again is ignored after its first chunk, so a text has one value.
struct PngTexts {
    std::vector<PngText> texts;
    std::vector<std::string> ignored;
    const PngText* find(const std::string& keyword) const;  // null when absent
};

// What the file says of itself before its pixels: its size and the text chunks before its image data.
struct PngHeader {
    uint32_t width = 0, height = 0;
    PngTexts texts;
};

// The largest picture oasis decodes unless told otherwise (a reference this size renders for
// minutes on llvmpipe), and the most it ever decodes (the --size domain, 1..32768 a side, and at
// most 1 GiB of RGBA).
constexpr uint32_t kDefaultMaxPngSide = 4096;
constexpr uint32_t kMaxPngSide = 32768;
constexpr uint64_t kMaxPngDecodedBytes = uint64_t(1) << 30;

// Reads the signature, the header and every chunk before the image data of PNG bytes, decoding no
// pixel. False with `error` (never empty: "not a PNG file", "its header says 16384x16384 pixels;
// ...", "IHDR: CRC error", "the file ends inside its header") when they cannot be read or the
// picture is larger than `maxSide` a side or the decoded-bytes cap.
bool readPngHeader(const std::string& png, PngHeader& header, std::string& error, uint32_t maxSide = kDefaultMaxPngSide);
// The texts alone (readPngHeader with the largest limits); a file that cannot be read gives no texts
// and the reason among `ignored`.
PngTexts readPngTexts(const std::string& png);

// Decodes PNG bytes (any bit depth or colour type) to 8-bit RGBA, alpha 255 where it has none, after
// the same checks as readPngHeader. False with `error` (never empty) on a bad CRC, cut data, a
// picture over the limits.
bool decodePngBytes(const std::string& png, std::vector<uint8_t>& rgba, uint32_t& width, uint32_t& height,
                    std::string& error, uint32_t maxSide = kDefaultMaxPngSide);

}  // namespace oasis
