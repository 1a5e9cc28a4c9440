// PNG text chunks (render/png_text.h), written and read per the PNG specification's chunk layout:
// a 4-byte big-endian length, the 4-byte type, the data, and the CRC-32 of type and data.
#include "render/png_text.h"

#include <array>

namespace oasis {
namespace {

constexpr char kSignature[] = "\x89PNG\r\n\x1a\n";
constexpr size_t kSignatureBytes = 8;
constexpr size_t kIhdrEnd = kSignatureBytes + 4 + 4 + 13 + 4;  // signature, then IHDR: length, type, data, CRC
// Reasons kept for what was ignored; past this many the rest are counted, so a file of a million
// bad chunks cannot grow the report without bound.
constexpr size_t kMaxIgnoredReasons = 16;

// The byte-at-a-time table of the reflected polynomial, made at compile time.
constexpr std::array<uint32_t, 256> crcTable() {
    std::array<uint32_t, 256> table{};
    for (uint32_t n = 0; n < 256; ++n) {
        uint32_t c = n;
        for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
        table[n] = c;
    }
    return table;
}
constexpr std::array<uint32_t, 256> kCrcTable = crcTable();

uint32_t bigEndian32(const std::string& bytes, size_t at) {
    return uint32_t(uint8_t(bytes[at])) << 24 | uint32_t(uint8_t(bytes[at + 1])) << 16 |
           uint32_t(uint8_t(bytes[at + 2])) << 8 | uint32_t(uint8_t(bytes[at + 3]));
}

void appendBigEndian32(std::string& bytes, uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) bytes.push_back(char(uint8_t(value >> shift)));
}

// A chunk type for messages: its four letters, or its bytes in hex when they are not letters.
std::string typeName(const std::string& type) {
    bool letters = true;
    for (char c : type) letters = letters && ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'));
    if (letters) return type;
    static const char kHex[] = "0123456789abcdef";
    std::string hex = "0x";
    for (char c : type) hex += {kHex[uint8_t(c) >> 4], kHex[uint8_t(c) & 15]};
    return hex;
}

std::string latin1ToUtf8(const std::string& text) {
    std::string utf8;
    for (char c : text) {
        uint8_t byte = uint8_t(c);
        if (byte < 0x80) {
            utf8 += c;
        } else {
            utf8 += char(0xC0 | (byte >> 6));
            utf8 += char(0x80 | (byte & 0x3F));
        }
    }
    return utf8;
}

// Reads a text chunk's data into `text`, or says why it cannot be read.
std::string parseTextChunk(const std::string& type, const std::string& data, PngText& text) {
    size_t keywordEnd = data.find('\0');
    if (keywordEnd == std::string::npos) return "it has no keyword separator";
    text.keyword = data.substr(0, keywordEnd);
    std::string why;
    if (!validPngKeyword(text.keyword, &why)) return "its keyword " + why;
    if (type == "tEXt") {
        text.text = latin1ToUtf8(data.substr(keywordEnd + 1));
        return {};
    }
    // iTXt: compression flag, compression method, language tag NUL, translated keyword NUL, text.
    size_t at = keywordEnd + 1;
    if (data.size() < at + 2) return "it ends before its compression flag";
    if (data[at] != 0) return "its text is compressed (oasis reads uncompressed text only)";
    size_t languageEnd = data.find('\0', at + 2);
    size_t translatedEnd = languageEnd == std::string::npos ? languageEnd : data.find('\0', languageEnd + 1);
    if (translatedEnd == std::string::npos) return "it ends inside its language tag or translated keyword";
    text.text = validUtf8(data.substr(translatedEnd + 1));
    return {};
}

}  // namespace

uint32_t crc32(const void* data, size_t size, uint32_t crc) {
    const uint8_t* bytes = static_cast<const uint8_t*>(data);
    uint32_t c = crc ^ 0xFFFFFFFFu;
    for (size_t i = 0; i < size; ++i) c = kCrcTable[(c ^ bytes[i]) & 0xFF] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

bool validPngKeyword(const std::string& keyword, std::string* why) {
    auto fail = [&](const std::string& reason) {
        if (why) *why = reason;
        return false;
    };
    if (keyword.empty() || keyword.size() > 79)
        return fail("is " + std::to_string(keyword.size()) + " bytes long (PNG allows 1 to 79)");
    for (size_t i = 0; i < keyword.size(); ++i) {
        uint8_t c = uint8_t(keyword[i]);
        if (!((c >= 32 && c <= 126) || c >= 161)) return fail("holds a byte that is not printable Latin-1");
        if (c == ' ' && (i == 0 || i + 1 == keyword.size() || keyword[i + 1] == ' '))
            return fail("has a leading, trailing or double space");
    }
    return true;
}

std::string validUtf8(const std::string& text) {
    static const char kReplacement[] = "\xEF\xBF\xBD";
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size();) {
        uint8_t lead = uint8_t(text[i]);
        size_t length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
        bool valid = length > 0 && i + length <= text.size();
        uint32_t code = length == 1 ? lead : length == 2 ? lead & 0x1F : length == 3 ? lead & 0x0F : lead & 0x07;
        for (size_t k = 1; valid && k < length; ++k) {
            uint8_t next = uint8_t(text[i + k]);
            valid = (next & 0xC0) == 0x80;
            code = code << 6 | (next & 0x3F);
        }
        // Overlong forms, UTF-16 surrogates and code points past U+10FFFF are not UTF-8 either.
        static const uint32_t kSmallest[] = {0, 0, 0x80, 0x800, 0x10000};
        valid = valid && code >= kSmallest[length] && code <= 0x10FFFF && !(code >= 0xD800 && code <= 0xDFFF);
        if (valid) {
            out.append(text, i, length);
            i += length;
        } else {
            out += kReplacement;
            i += 1;
        }
    }
    return out;
}

bool pngTextChunk(const PngText& text, std::string& chunk, std::string& error) {
    std::string why;
    if (!validPngKeyword(text.keyword, &why)) {
        error = "the PNG text keyword '" + text.keyword + "' " + why;
        return false;
    }
    std::string data = text.keyword;
    data += std::string("\0\0\0\0\0", 5);  // keyword end, not compressed, method 0, no language, no translation
    data += validUtf8(text.text);
    if (data.size() > kMaxPngTextBytes) {
        error = "the PNG text '" + text.keyword + "' is " + std::to_string(data.size()) + " bytes, over " +
                std::to_string(kMaxPngTextBytes);
        return false;
    }
    std::string typeAndData = "iTXt" + data;
    chunk.clear();
    appendBigEndian32(chunk, uint32_t(data.size()));
    chunk += typeAndData;
    appendBigEndian32(chunk, crc32(typeAndData.data(), typeAndData.size()));
    return true;
}

bool insertPngTexts(std::string& png, const std::vector<PngText>& texts, std::string& error) {
    if (png.size() < kIhdrEnd || png.compare(0, kSignatureBytes, kSignature, kSignatureBytes) != 0 ||
        bigEndian32(png, kSignatureBytes) != 13 || png.compare(kSignatureBytes + 4, 4, "IHDR") != 0) {
        error = "not PNG bytes with an IHDR chunk first: no place for its text";
        return false;
    }
    std::string chunks, chunk;
    for (const PngText& text : texts) {
        if (!pngTextChunk(text, chunk, error)) return false;
        chunks += chunk;
    }
    png.insert(kIhdrEnd, chunks);
    return true;
}

const PngText* PngTexts::find(const std::string& keyword) const {
    for (const PngText& text : texts)
        if (text.keyword == keyword) return &text;
    return nullptr;
}

PngTexts readPngTexts(const std::string& png) {
    PngTexts result;
    size_t ignoredCount = 0;
    auto ignore = [&](const std::string& why) {
        if (++ignoredCount <= kMaxIgnoredReasons) result.ignored.push_back(why);
    };
    if (png.size() < kSignatureBytes || png.compare(0, kSignatureBytes, kSignature, kSignatureBytes) != 0) {
        ignore("not a PNG (no PNG signature)");
        return result;
    }
    bool full = false;
    for (size_t at = kSignatureBytes; at < png.size();) {
        std::string where = " at byte " + std::to_string(at);
        if (png.size() - at < 12) {
            ignore(std::to_string(png.size() - at) + " bytes" + where + " are too few for a chunk: the file is cut");
            break;
        }
        uint32_t length = bigEndian32(png, at);
        std::string type = png.substr(at + 4, 4);
        std::string name = "the " + typeName(type) + " chunk" + where;
        if (length > 0x7FFFFFFFu || length > png.size() - at - 12) {
            ignore(name + " claims " + std::to_string(length) + " bytes, past the end of the file: the rest is unread");
            break;
        }
        size_t next = at + 12 + length;
        if (type == "IEND") break;
        bool text = type == "tEXt" || type == "iTXt";
        if (type == "zTXt") {
            ignore(name + " is compressed (oasis reads uncompressed text only)");
        } else if (text && full) {
            ignore(name + " is past the " + std::to_string(kMaxPngTexts) + " text chunks oasis reads");
        } else if (text && length > kMaxPngTextBytes) {
            ignore(name + " holds " + std::to_string(length) + " bytes, over the " + std::to_string(kMaxPngTextBytes) +
                   " oasis reads");
        } else if (text) {
            if (crc32(png.data() + at + 4, 4 + size_t(length)) != bigEndian32(png, at + 8 + length)) {
                ignore(name + " fails its CRC");
            } else {
                PngText entry;
                std::string why = parseTextChunk(type, png.substr(at + 8, length), entry);
                if (!why.empty()) ignore(name + ": " + why);
                else if (result.find(entry.keyword)) ignore(name + " repeats the keyword '" + entry.keyword + "' (the first kept)");
                else result.texts.push_back(std::move(entry));
                full = result.texts.size() >= kMaxPngTexts;
            }
        }
        at = next;
    }
    if (ignoredCount > kMaxIgnoredReasons)
        result.ignored.push_back("and " + std::to_string(ignoredCount - kMaxIgnoredReasons) + " more");
    return result;
}

}  // namespace oasis
