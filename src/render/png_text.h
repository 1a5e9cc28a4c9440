// PNG text chunks: written into encoded PNG bytes (iTXt, uncompressed UTF-8) and read back from
// them (tEXt and uncompressed iTXt), with PNG's CRC-32. oasis keeps its provenance there
// (commands/provenance.h); decoders that do not know the chunks skip them.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace oasis {

struct PngText {
    std::string keyword;  // 1..79 bytes of printable Latin-1, no leading, trailing or double spaces
    std::string text;     // UTF-8 (iTXt); a tEXt chunk's Latin-1 is converted to UTF-8 when read
};

// What a reader keeps: at most this many text chunks, each of at most this many bytes of data.
constexpr size_t kMaxPngTexts = 64;
constexpr size_t kMaxPngTextBytes = size_t(64) << 10;

// CRC-32 as PNG (and zlib) compute it: polynomial 0xEDB88320 (reflected), initial and final value
// 0xFFFFFFFF. `crc` continues an earlier call's result over more bytes.
uint32_t crc32(const void* data, size_t size, uint32_t crc = 0);

// Whether `keyword` is one PNG allows (the rule above); `why` says what is wrong otherwise.
bool validPngKeyword(const std::string& keyword, std::string* why = nullptr);

// `text` with every byte that is not part of valid UTF-8 replaced by U+FFFD (a path in a command
// line may be in another encoding; iTXt holds UTF-8 only).
std::string validUtf8(const std::string& text);

// One whole iTXt chunk (length, type, data, CRC) holding `text` uncompressed, with no language tag.
// False with `error` when the keyword is not valid or the data would exceed kMaxPngTextBytes.
bool pngTextChunk(const PngText& text, std::string& chunk, std::string& error);

// Inserts one iTXt chunk per entry right after the IHDR chunk of the PNG bytes `png` (where the
// format lets text chunks describe the image before its data). False with `error`, `png` as it
// was, when `png` does not start with a signature and an IHDR chunk or a chunk cannot be made.
bool insertPngTexts(std::string& png, const std::vector<PngText>& texts, std::string& error);

// The text chunks of PNG bytes, in file order, and what was left out and why ("a tEXt chunk at
// byte 33 fails its CRC", "a zTXt chunk (compressed) ...", "the chunk at byte N runs past the
// end of the file"). Never throws: malformed input gives fewer texts and more reasons. A keyword
// that appears again is ignored after its first chunk, so a text has one value.
struct PngTexts {
    std::vector<PngText> texts;
    std::vector<std::string> ignored;
    const PngText* find(const std::string& keyword) const;  // null when absent
};
PngTexts readPngTexts(const std::string& png);

}  // namespace oasis
