// PNG text chunks (io/png_text.h): the keyword rule PNG sets and the lookup of a text; the
// files themselves are written and read by png_libpng.cpp.
#include "io/png_text.h"

namespace oasis {

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

const PngText* PngTexts::find(const std::string& keyword) const {
    for (const PngText& text : texts)
        if (text.keyword == keyword) return &text;
    return nullptr;
}

}  // namespace oasis
