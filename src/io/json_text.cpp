// JSON text pieces for the hand-written reports (io/json_text.h).
#include "io/json_text.h"

#include <cmath>
#include <cstdio>

namespace oasis {

std::string jsonString(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", unsigned(static_cast<unsigned char>(c)));
            out += escaped;
            continue;
        }
        out += c;
    }
    return out + "\"";
}

std::string jsonNumber(double value, int decimals) {
    if (!std::isfinite(value)) return "null";
    char text[64];
    std::snprintf(text, sizeof(text), "%.*f", decimals, value);
    return text;
}

std::string numberList(const std::vector<double>& values, const char* separator, const char* format,
                       bool nonFiniteAsNull) {
    std::string text;
    char number[40];
    for (size_t i = 0; i < values.size(); ++i) {
        if (nonFiniteAsNull && !std::isfinite(values[i])) {
            std::snprintf(number, sizeof number, "null");
        } else {
            std::snprintf(number, sizeof number, format, values[i]);
        }
        text += (i ? separator : "") + std::string(number);
    }
    return text;
}

}  // namespace oasis
