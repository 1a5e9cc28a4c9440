// printableText (io/printable_text.h): one pass over the bytes, UTF-8 sequences checked as
// RFC 3629 defines them (no overlong forms, no surrogates, nothing past U+10FFFF).
#include "io/printable_text.h"

#include <cstdint>
#include <cstdio>

namespace oasis {
namespace {

// The length of the valid UTF-8 sequence at `at` and its code point, or 0 when the byte there
// does not start one.
size_t utf8Sequence(const std::string& text, size_t at, uint32_t& code) {
    uint8_t lead = uint8_t(text[at]);
    size_t length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
    if (length == 0 || at + length > text.size()) return 0;
    code = length == 1 ? lead : length == 2 ? lead & 0x1F : length == 3 ? lead & 0x0F : lead & 0x07;
    for (size_t k = 1; k < length; ++k) {
        uint8_t next = uint8_t(text[at + k]);
        if ((next & 0xC0) != 0x80) return 0;
        code = code << 6 | (next & 0x3F);
    }
    static const uint32_t kSmallest[] = {0, 0, 0x80, 0x800, 0x10000};
    bool valid = code >= kSmallest[length] && code <= 0x10FFFF && !(code >= 0xD800 && code <= 0xDFFF);
    return valid ? length : 0;
}

}  // namespace

std::string printableText(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    char escaped[8];
    for (size_t i = 0; i < text.size();) {
        uint32_t code = 0;
        size_t length = utf8Sequence(text, i, code);
        if (length == 0) {
            std::snprintf(escaped, sizeof escaped, "\\x%02X", unsigned(uint8_t(text[i])));
            out += escaped;
            i += 1;
            continue;
        }
        if (code == '\\') out += "\\\\";
        else if (code == '\n') out += "\\n";
        else if (code == '\r') out += "\\r";
        else if (code == '\t') out += "\\t";
        else if (code < 0x20 || (code >= 0x7F && code <= 0x9F)) {
            std::snprintf(escaped, sizeof escaped, "\\u%04X", unsigned(code));
            out += escaped;
        } else {
            out.append(text, i, length);
        }
        i += length;
    }
    return out;
}

std::string validUtf8(const std::string& text) {
    static const char kReplacement[] = "\xEF\xBF\xBD";
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size();) {
        uint32_t code = 0;
        size_t length = utf8Sequence(text, i, code);
        if (length) out.append(text, i, length);
        else out += kReplacement;
        i += length ? length : 1;
    }
    return out;
}

}  // namespace oasis
