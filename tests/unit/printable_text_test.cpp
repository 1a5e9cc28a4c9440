// Covers src/io/printable_text.h: every byte a terminal could act on comes out spelled, valid
// UTF-8 comes out as it went in, and the escaping cannot be forged (a backslash is escaped too).
#include <gtest/gtest.h>

#include <string>

#include "io/printable_text.h"

namespace oasis {
namespace {

TEST(PrintableText, SpellsControlBytesAsJsonDoes) {
    EXPECT_EQ(printableText("plain text.png"), "plain text.png");
    EXPECT_EQ(printableText("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80"), "caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80");
    EXPECT_EQ(printableText("a\x1b[2Jb"), "a\\u001B[2Jb");
    EXPECT_EQ(printableText("line\nnext\rover\ttab"), "line\\nnext\\rover\\ttab");
    EXPECT_EQ(printableText(std::string("nul\0end", 7)), "nul\\u0000end");
    EXPECT_EQ(printableText("bell\x07 del\x7f"), "bell\\u0007 del\\u007F");
    EXPECT_EQ(printableText("csi \xC2\x9B" "31m"), "csi \\u009B31m");  // U+009B, a C1 control
    EXPECT_EQ(printableText("back\\slash"), "back\\\\slash");
}

TEST(PrintableText, SpellsInvalidUtf8AsBytes) {
    EXPECT_EQ(printableText("a\xFF" "b"), "a\\xFFb");
    EXPECT_EQ(printableText("\xC0\xAF"), "\\xC0\\xAF");              // an overlong '/'
    EXPECT_EQ(printableText("\xED\xA0\x80"), "\\xED\\xA0\\x80");      // a surrogate
    EXPECT_EQ(printableText("cut \xE2\x82"), "cut \\xE2\\x82");
    EXPECT_EQ(printableText("\x9B"), "\\x9B");                        // a raw C1 byte is not UTF-8
}

TEST(PrintableText, NoRawControlByteEverComesOut) {
    std::string all;
    for (int byte = 0; byte < 256; ++byte) all += char(byte);
    std::string out = printableText(all);
    for (unsigned char c : out) EXPECT_TRUE(c >= 0x20 && c != 0x7F && c < 0x80) << int(c);
}

}  // namespace
}  // namespace oasis
