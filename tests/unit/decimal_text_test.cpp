// parseDecimal (io/decimal_text.h) gives std::from_chars's answers: the same double, and false
// where from_chars reports result_out_of_range or stops before the end of the text.
#include <gtest/gtest.h>

#include <charconv>
#include <cstring>

#include "io/decimal_text.h"

namespace oasis {
namespace {

TEST(DecimalText, AgreesWithFromChars) {
    const char* texts[] = {"0", "-0", "1", "0.1", "-12.5e3", "1E+2", "6.02214076e23", "123456789012345678901234567890",
                           "1.7976931348623157e308", "1.8e308", "1e400", "-1e400", "1e-310", "4.9e-324",
                           "2.5e-324", "2e-324", "1e-400", "0e-500", "0.30000000000000004", "9007199254740993"};
    for (const char* text : texts) {
        double expected = -7.0, got = -7.0;
        auto [end, status] = std::from_chars(text, text + std::strlen(text), expected);
        bool ok = status == std::errc() && end == text + std::strlen(text);
        EXPECT_EQ(parseDecimal(text, got), ok) << text;
        if (ok) EXPECT_EQ(std::memcmp(&got, &expected, sizeof got), 0) << text << ": " << got << " vs " << expected;
        else EXPECT_EQ(got, -7.0) << text << ": a failed read leaves the value";
    }
}

TEST(DecimalText, TheWholeTextOrNothing) {
    double value = 0.0;
    for (const char* text : {"", "1x", "1.5 ", " 1.5", "--1", "1e", "inf", "nan", "0x10", "1,5"})
        EXPECT_FALSE(parseDecimal(text, value)) << "'" << text << "'";
}

}  // namespace
}  // namespace oasis
