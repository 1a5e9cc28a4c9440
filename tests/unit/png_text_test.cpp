// Covers src/io/png_text.h (libpng underneath): text chunks written and read back (stb_image, a
// second decoder, agrees on the pixels), chunks written by others, malformed chunks left out with
// a reason, a header over the limits refused before any pixel is decoded, a decompression bomb in a
// text chunk refused, a cut file and a bad CRC reported with a message that is never empty.
#include <gtest/gtest.h>
#include <zlib.h>

#include <chrono>
#include <cstring>
#include <string>
#include <vector>

#include "render/image.h"
#include "io/png_text.h"

#include <stb_image.h>

#include "unit_support.h"

namespace oasis {
namespace {

using namespace unittest;

void appendBigEndian32(std::string& bytes, uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) bytes.push_back(char(uint8_t(value >> shift)));
}

// A chunk made by hand (the reader's input need not come from the writer): `crcDelta` spoils its
// CRC (zlib's crc32, which PNG's is).
std::string chunk(const std::string& type, const std::string& data, uint32_t crcDelta = 0) {
    std::string bytes;
    appendBigEndian32(bytes, uint32_t(data.size()));
    bytes += type + data;
    std::string typed = type + data;
    uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(typed.data()), uInt(typed.size()));
    appendBigEndian32(bytes, uint32_t(crc) + crcDelta);
    return bytes;
}

std::string encoded(const std::vector<PngText>& texts = {}, const Image& image = pattern(9, 4)) {
    std::string png;
    EXPECT_TRUE(encodePng(image, png, texts));
    return png;
}

// The PNG's bytes with `chunks` inserted after IHDR (byte 33).
std::string withChunks(const std::string& chunks) {
    std::string png = encoded();
    png.insert(33, chunks);
    return png;
}

// A signature and an IHDR claiming `width` x `height` RGBA pixels, then `rest`.
std::string header(uint32_t width, uint32_t height, const std::string& rest = "") {
    std::string data;
    appendBigEndian32(data, width);
    appendBigEndian32(data, height);
    data += std::string("\x08\x06\x00\x00\x00", 5);
    return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", data) + rest;
}

bool mentions(const std::vector<std::string>& reasons, const std::string& part) {
    for (const std::string& reason : reasons)
        if (reason.find(part) != std::string::npos) return true;
    return false;
}

TEST(PngText, RoundTripBeforeTheDataAndStbImageAgrees) {
    const std::vector<PngText> texts = {{"oasis:version", "0.1 (git abc)"},
                                        {"oasis:options", "--size 9x4 --hour 18"},
                                        {"oasis:command", "oasis render --out 'caf\xC3\xA9 frame.png'"},
                                        {"empty", ""}};
    std::string png = encoded(texts);
    EXPECT_EQ(png.compare(37, 4, "iTXt"), 0) << "the first text chunk follows IHDR";
    PngTexts read = readPngTexts(png);
    EXPECT_TRUE(read.ignored.empty()) << read.ignored.front();
    ASSERT_EQ(read.texts.size(), texts.size());
    for (size_t k = 0; k < texts.size(); ++k) {
        EXPECT_EQ(read.texts[k].keyword, texts[k].keyword);
        EXPECT_EQ(read.texts[k].text, texts[k].text);
    }
    ASSERT_NE(read.find("oasis:options"), nullptr);
    EXPECT_EQ(read.find("oasis:options")->text, "--size 9x4 --hour 18");
    EXPECT_EQ(read.find("nope"), nullptr);

    Image image = pattern(9, 4);
    int w = 0, h = 0, channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(png.data()), int(png.size()), &w, &h,
                                            &channels, 4);
    ASSERT_NE(pixels, nullptr) << stbi_failure_reason();
    EXPECT_EQ(w, 9);
    EXPECT_EQ(h, 4);
    EXPECT_EQ(std::memcmp(pixels, image.rgba.data(), image.rgba.size()), 0);
    stbi_image_free(pixels);
    std::vector<uint8_t> rgba;
    uint32_t width = 0, height = 0;
    std::string error;
    ASSERT_TRUE(decodePngBytes(png, rgba, width, height, error)) << error;
    EXPECT_EQ(rgba, image.rgba);
    EXPECT_TRUE(readPngTexts(encoded()).texts.empty());
    EXPECT_TRUE(readPngTexts(encoded()).ignored.empty());
}

TEST(PngText, ReadsTextChunksWrittenByOthers) {
    // tEXt is Latin-1 (0xE9 is é), read as UTF-8; an iTXt chunk with a language tag and translation.
    std::string png = withChunks(chunk("tEXt", std::string("Author\0Ren\xE9", 11)) +
                                 chunk("iTXt", std::string("Title\0\0\0en\0Titel\0Bild", 21)));
    PngTexts read = readPngTexts(png);
    ASSERT_EQ(read.texts.size(), 2u);
    EXPECT_EQ(read.texts[0].text, "Ren\xC3\xA9");
    EXPECT_EQ(read.texts[1].keyword, "Title");
    EXPECT_EQ(read.texts[1].text, "Bild");
}

TEST(PngText, InvalidUtf8IsReplacedNotPassedOn) {
    EXPECT_EQ(validUtf8("ok \xC3\xA9"), "ok \xC3\xA9");
    EXPECT_EQ(validUtf8("a\xFF" "b"), "a\xEF\xBF\xBD" "b");
    EXPECT_EQ(validUtf8("\xC0\xAF"), "\xEF\xBF\xBD\xEF\xBF\xBD");  // an overlong '/'
    EXPECT_EQ(validUtf8("\xED\xA0\x80"), "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD");  // a surrogate
    EXPECT_EQ(validUtf8("cut \xE2\x82"), "cut \xEF\xBF\xBD\xEF\xBF\xBD");
    PngTexts read = readPngTexts(encoded({{"path", "/tmp/\xFF.png"}}));
    ASSERT_EQ(read.texts.size(), 1u);
    EXPECT_EQ(read.texts[0].text, "/tmp/\xEF\xBF\xBD.png");
}

TEST(PngText, MalformedChunksAreLeftOutWithAReason) {
    std::string good = chunk("iTXt", std::string("kept\0\0\0\0\0yes", 12));
    struct Case {
        std::string chunks, reason;
    } cases[] = {
        {chunk("tEXt", std::string("k\0v", 3), 1), "CRC error"},
        {chunk("tEXt", std::string("kept\0again", 10)), "repeats the keyword"},
        {chunk("tEXt", "k" + std::string(1, '\0') + std::string(kMaxPngTextBytes, 'x')), "over the"},
        {chunk("tEXt", std::string("bad\x01key\0v", 9)), "not printable Latin-1"},
    };
    for (const Case& c : cases) {
        PngTexts read = readPngTexts(withChunks(good + c.chunks));
        ASSERT_EQ(read.texts.size(), 1u) << c.reason;
        EXPECT_EQ(read.texts[0].keyword, "kept");
        ASSERT_FALSE(read.ignored.empty()) << c.reason;
        EXPECT_TRUE(mentions(read.ignored, c.reason)) << c.reason << ": " << read.ignored.front();
    }
    EXPECT_TRUE(mentions(readPngTexts("GIF89a").ignored, "not a PNG"));
    EXPECT_TRUE(mentions(readPngTexts("").ignored, "not a PNG"));
}

TEST(PngText, ReadsAtMostTheLimitAndBoundsItsReasons) {
    std::string many;
    for (size_t k = 0; k < kMaxPngTexts + 3; ++k) many += chunk("tEXt", "k" + std::to_string(k) + '\0' + "v");
    PngTexts read = readPngTexts(withChunks(many));
    EXPECT_EQ(read.texts.size(), kMaxPngTexts);
    EXPECT_TRUE(mentions(read.ignored, "past the 64 text chunks"));
    std::string bad;
    for (int k = 0; k < 1000; ++k) bad += chunk("tEXt", "k\0v", 1);
    read = readPngTexts(withChunks(bad));
    EXPECT_TRUE(read.texts.empty());
    EXPECT_LE(read.ignored.size(), 17u);
}

// Issue 42: a 16384x16384 header is judged before any pixel (no data is even present), in far
// less than a second, with the size in the message; --allow-large's limit admits it.
TEST(PngText, AHeaderOverTheLimitIsRefusedBeforeTheData) {
    std::string png = header(16384, 16384, chunk("tEXt", std::string("oasis:view\0final", 16)) + chunk("IDAT", "x"));
    auto start = std::chrono::steady_clock::now();
    PngHeader read;
    std::string error;
    EXPECT_FALSE(readPngHeader(png, read, error));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 0.5);
    EXPECT_NE(error.find("its header says 16384x16384 pixels; oasis reads at most 4096 a side"), std::string::npos)
        << error;
    EXPECT_NE(error.find("--allow-large"), std::string::npos) << error;
    EXPECT_TRUE(readPngHeader(png, read, error, kMaxPngSide)) << error;
    EXPECT_EQ(read.width, 16384u);
    ASSERT_NE(read.texts.find("oasis:view"), nullptr);
    // Past the --size domain, and past what libpng's own limit lets through.
    EXPECT_FALSE(readPngHeader(header(32769, 1), read, error, kMaxPngSide));
    EXPECT_NE(error.find("32769x1"), std::string::npos) << error;
    EXPECT_FALSE(readPngHeader(header(100000, 100000), read, error, kMaxPngSide));
    EXPECT_NE(error.find("100000x100000"), std::string::npos) << error;
    EXPECT_FALSE(readPngHeader(header(2000000, 1), read, error, kMaxPngSide));
    EXPECT_FALSE(error.empty());
    std::vector<uint8_t> rgba;
    uint32_t w = 0, h = 0;
    EXPECT_FALSE(decodePngBytes(png, rgba, w, h, error));
    EXPECT_TRUE(rgba.empty());
}

// A zTXt chunk of a few KiB that inflates to 64 MiB: libpng's chunk cap stops the inflation, the
// chunk is left out with a reason and the picture still decodes.
TEST(PngText, ACompressedTextBombIsRefusedNotInflated) {
    std::string zeros(size_t(64) << 20, 'a');
    uLongf size = compressBound(uLong(zeros.size()));
    std::string packed(size, '\0');
    ASSERT_EQ(compress2(reinterpret_cast<Bytef*>(&packed[0]), &size, reinterpret_cast<const Bytef*>(zeros.data()),
                        uLong(zeros.size()), 9), Z_OK);
    packed.resize(size);
    std::string png = withChunks(chunk("zTXt", std::string("bomb\0\0", 6) + packed));
    auto start = std::chrono::steady_clock::now();
    PngTexts read = readPngTexts(png);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
    EXPECT_EQ(read.find("bomb"), nullptr);
    EXPECT_FALSE(read.ignored.empty());
    std::vector<uint8_t> rgba;
    uint32_t w = 0, h = 0;
    std::string error;
    EXPECT_TRUE(decodePngBytes(png, rgba, w, h, error)) << error;
}

// A cut file and a spoilt image-data CRC fail with a reason that is never empty ("not a readable
// PNG ()" was issue 42's); every cut and every flipped byte is read without a crash.
TEST(PngText, CutFilesAndBadCrcsAreReported) {
    std::string png = encoded({{"oasis:view", "final"}}, pattern(40, 30));
    std::vector<uint8_t> rgba;
    uint32_t w = 0, h = 0;
    std::string error;
    for (size_t at = 0; at < png.size(); ++at) {
        error.clear();
        EXPECT_FALSE(decodePngBytes(png.substr(0, at), rgba, w, h, error)) << "cut at " << at;
        EXPECT_FALSE(error.empty()) << "cut at " << at;
        EXPECT_EQ(error.find("()"), std::string::npos) << error;
    }
    size_t idat = png.find("IDAT");
    ASSERT_NE(idat, std::string::npos);
    uint32_t length = uint32_t(uint8_t(png[idat - 4])) << 24 | uint32_t(uint8_t(png[idat - 3])) << 16 |
                      uint32_t(uint8_t(png[idat - 2])) << 8 | uint32_t(uint8_t(png[idat - 1]));
    std::string bad = png;
    bad[idat + 4 + length] ^= 0x10;  // the image data as written, its CRC spoilt
    EXPECT_FALSE(decodePngBytes(bad, rgba, w, h, error));
    EXPECT_NE(error.find("CRC"), std::string::npos) << error;
    for (size_t at = 0; at < png.size(); ++at) {
        std::string flipped = png;
        flipped[at] = char(uint8_t(flipped[at]) ^ 0x80);
        error.clear();
        if (!decodePngBytes(flipped, rgba, w, h, error)) EXPECT_FALSE(error.empty()) << "byte " << at;
        PngTexts read = readPngTexts(flipped);
        for (const PngText& text : read.texts) EXPECT_EQ(text.text, "final") << "byte " << at;
    }
}

}  // namespace
}  // namespace oasis
