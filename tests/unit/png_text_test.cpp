// Covers src/render/png_text.h: the CRC-32 against known values, text chunks written into encoded
// PNGs and read back (stb_image still decodes the pixels), and malformed chunks read without a
// crash, each left out with its reason.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "render/image.h"
#include "render/png_text.h"

#include <stb_image.h>

namespace oasis {
namespace {

Image pattern(int w, int h) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c) image.pixel(x, y)[c] = uint8_t((x * 7 + y * 31 + c * 64) & 255);
    return image;
}

void appendBigEndian32(std::string& bytes, uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) bytes.push_back(char(uint8_t(value >> shift)));
}

// A chunk made by hand (the reader's input need not come from the writer): `crcDelta` spoils its CRC.
std::string chunk(const std::string& type, const std::string& data, uint32_t crcDelta = 0) {
    std::string bytes;
    appendBigEndian32(bytes, uint32_t(data.size()));
    bytes += type + data;
    appendBigEndian32(bytes, crc32((type + data).data(), type.size() + data.size()) + crcDelta);
    return bytes;
}

std::string encoded(const std::vector<PngText>& texts = {}) {
    std::string png;
    EXPECT_TRUE(encodePng(pattern(9, 4), png, texts));
    return png;
}

// The PNG's bytes with `chunks` inserted after IHDR (byte 33).
std::string withChunks(const std::string& chunks) {
    std::string png = encoded();
    png.insert(33, chunks);
    return png;
}

bool mentions(const std::vector<std::string>& reasons, const std::string& part) {
    for (const std::string& reason : reasons)
        if (reason.find(part) != std::string::npos) return true;
    return false;
}

TEST(Crc32, KnownValues) {
    EXPECT_EQ(crc32("123456789", 9), 0xCBF43926u);  // the CRC-32 check value
    EXPECT_EQ(crc32("IEND", 4), 0xAE426082u);       // every PNG's last four bytes
    EXPECT_EQ(crc32("", 0), 0u);
    EXPECT_EQ(crc32("56789", 5, crc32("1234", 4)), 0xCBF43926u);  // continued over a second call
}

TEST(PngTextChunk, LayoutAndCrcOfAKnownChunk) {
    std::string bytes, error;
    ASSERT_TRUE(pngTextChunk({"oasis:view", "final"}, bytes, error)) << error;
    const std::string data("oasis:view\0\0\0\0\0final", 20);
    std::string expected;
    appendBigEndian32(expected, 20);
    expected += "iTXt" + data;
    appendBigEndian32(expected, 0x99539C1Au);  // zlib.crc32(b"iTXt" + data), computed outside oasis
    EXPECT_EQ(bytes, expected);
}

TEST(PngTextChunk, RefusesBadKeywordsAndOversizedText) {
    std::string bytes, error;
    for (const std::string keyword : {std::string(), std::string(80, 'k'), std::string(" lead"), std::string("trail "),
                                      std::string("two  spaces"), std::string("tab\there"), std::string("nul\0x", 5)}) {
        EXPECT_FALSE(pngTextChunk({keyword, "x"}, bytes, error)) << keyword;
        EXPECT_NE(error.find("keyword"), std::string::npos) << error;
    }
    EXPECT_TRUE(pngTextChunk({std::string(79, 'k'), "x"}, bytes, error)) << error;
    EXPECT_FALSE(pngTextChunk({"big", std::string(kMaxPngTextBytes, 'x')}, bytes, error));
    EXPECT_NE(error.find("over"), std::string::npos) << error;
}

TEST(PngText, RoundTripAfterTheHeaderAndStbImageStillDecodes) {
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
    // Without texts the encoder's bytes are as before: no chunk is added.
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
        {chunk("tEXt", std::string("k\0v", 3), 1), "fails its CRC"},
        {chunk("zTXt", std::string("k\0\0xx", 5)), "compressed"},
        {chunk("iTXt", std::string("k\0\1\0\0\0xx", 8)), "compressed"},
        {chunk("tEXt", "no separator"), "no keyword separator"},
        {chunk("tEXt", std::string("\0v", 2)), "keyword is 0 bytes"},
        {chunk("iTXt", std::string("k\0", 2)), "before its compression flag"},
        {chunk("iTXt", std::string("k\0\0\0en", 6)), "language tag"},
        {chunk("tEXt", std::string("kept\0again", 10)), "repeats the keyword 'kept'"},
        {chunk("tEXt", "k" + std::string(1, '\0') + std::string(kMaxPngTextBytes, 'x')), "over the"},
    };
    for (const Case& c : cases) {
        PngTexts read = readPngTexts(withChunks(good + c.chunks));
        ASSERT_EQ(read.texts.size(), 1u) << c.reason;
        EXPECT_EQ(read.texts[0].keyword, "kept");
        EXPECT_TRUE(mentions(read.ignored, c.reason)) << c.reason << ": " << read.ignored.front();
    }
    // A length past the end, a cut file, no signature: what came before is kept, the rest unread.
    std::string png = withChunks(good);
    std::string liar = png.substr(0, 33) + good;
    appendBigEndian32(liar, 0x7FFFFFF0u);
    liar += "tEXtdata";
    EXPECT_TRUE(mentions(readPngTexts(liar).ignored, "past the end of the file"));
    EXPECT_EQ(readPngTexts(liar).texts.size(), 1u);
    EXPECT_TRUE(mentions(readPngTexts(png.substr(0, 33 + good.size() + 5)).ignored, "too few for a chunk"));
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
    EXPECT_EQ(read.ignored.back(), "and 984 more");
}

// Every single-byte change and every cut of a PNG with texts is read without a crash, and a
// changed byte inside a text chunk never yields a changed text (the CRC catches it).
TEST(PngText, EveryCorruptionIsReadSafely) {
    std::string png = encoded({{"oasis:view", "final"}, {"oasis:pipeline", "deferred"}});
    size_t textEnd = 33 + 2 * 12 + std::string("oasis:view\0\0\0\0\0final").size() +
                     std::string("oasis:pipeline\0\0\0\0\0deferred").size();
    for (size_t at = 0; at < png.size(); ++at) {
        for (uint8_t flip : {uint8_t(0x01), uint8_t(0x80), uint8_t(0xFF)}) {
            std::string bad = png;
            bad[at] = char(uint8_t(bad[at]) ^ flip);
            PngTexts read = readPngTexts(bad);
            if (at >= 33 && at < textEnd) {
                for (const PngText& text : read.texts)
                    EXPECT_TRUE((text.keyword == "oasis:view" && text.text == "final") ||
                                (text.keyword == "oasis:pipeline" && text.text == "deferred"))
                        << "byte " << at << ": " << text.keyword << " = " << text.text;
                // Either the chunk is left out with a reason, or its type no longer names a text chunk.
                EXPECT_TRUE(!read.ignored.empty() || read.texts.size() < 2) << "byte " << at;
            }
        }
        readPngTexts(png.substr(0, at));
    }
}

}  // namespace
}  // namespace oasis
