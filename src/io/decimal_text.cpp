// Decimal text (io/decimal_text.h): parseDecimal is strtod over a copy whose decimal point is the
// C locale's own; formatNumber is snprintf.
#include "io/decimal_text.h"

#include <cerrno>
#include <clocale>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace oasis {

bool parseDecimal(std::string_view text, double& value) {
    if (text.empty()) return false;
    std::string copy(text);
    // Decimal digits, sign, point and exponent only: strtod alone would also take leading space,
    // hexadecimal ("0x10"), "inf" and "nan", which from_chars's general format does not.
    if (copy.find_first_not_of("0123456789+-.eE") != std::string::npos) return false;
    // strtod reads the decimal point of LC_NUMERIC; the text has '.', so hand it the locale's.
    const char* point = std::localeconv()->decimal_point;
    if (point && point[0] && std::string(point) != ".") {
        size_t dot = copy.find('.');
        if (dot != std::string::npos) copy.replace(dot, 1, point);
    }
    errno = 0;
    char* end = nullptr;
    double parsed = std::strtod(copy.c_str(), &end);
    if (end != copy.c_str() + copy.size()) return false;
    if (!std::isfinite(parsed)) return false;                // overflow (or "inf", "nan")
    if (errno == ERANGE && parsed == 0.0) return false;      // a nonzero number too small for a double
    value = parsed;
    return true;
}

std::string formatNumber(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof(text), pattern, value);
    return text;
}

}  // namespace oasis
