// The few pieces of JSON text the probe's reports write (--shading, --history): a quoted string and
// a list of numbers, where a number that is not finite is null (JSON has no NaN or infinity).
#pragma once
#include <string>
#include <vector>

namespace oasis {

std::string jsonQuoted(const std::string& text);
// `format` is printf's for one double ("%.9g"); `separator` between them (", " for JSON).
std::string numberList(const std::vector<double>& values, const char* separator, const char* format,
                       bool nonFiniteAsNull = false);

}  // namespace oasis
