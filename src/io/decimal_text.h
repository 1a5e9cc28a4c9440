// Decimal numbers as text. Reading one as a double, the same on every platform and in every locale:
// the native build's libstdc++ and the web build's libc++ (emscripten 3.1.6, which has no
// std::from_chars for double) give the same answers, which are std::from_chars's. Writing one with
// a printf pattern, for the reports' tables.
#pragma once
#include <string>
#include <string_view>

namespace oasis {

// `text` (e.g. "-12.5e3": strtod's decimal form; callers check their own grammar first) read as a
// double with '.' as the decimal point whatever the C locale says. True only when the whole text is
// the number and its value is finite and representable: false for an overflow, and for a nonzero
// number that rounds to 0 (subnormals are fine), as std::from_chars reports result_out_of_range.
bool parseDecimal(std::string_view text, double& value);

// `value` written by printf's `pattern` for one double ("%.2f", "%.3g"), up to 63 characters.
std::string formatNumber(const char* pattern, double value);

}  // namespace oasis
