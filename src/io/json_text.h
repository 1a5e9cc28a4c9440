// The pieces of JSON text oasis's reports write by hand (caps, compare, bench, check, probe): a
// quoted string, a number and a list of numbers, where a number that is not finite is null (JSON has
// no NaN or infinity). One of each, so every report escapes and rounds alike.
#pragma once
#include <string>
#include <vector>

namespace oasis {

// `text` quoted, '"' and '\\' escaped and every control byte as \u00XX.
std::string jsonString(const std::string& text);
// A number as JSON: finite values with `decimals`, anything else as null.
std::string jsonNumber(double value, int decimals = 4);
// `format` is printf's for one double ("%.9g"); `separator` between them (", " for JSON).
std::string numberList(const std::vector<double>& values, const char* separator, const char* format,
                       bool nonFiniteAsNull = false);

}  // namespace oasis
