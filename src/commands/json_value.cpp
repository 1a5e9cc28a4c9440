// The JSON reader (commands/json_value.h): one function per grammar rule of RFC 8259, each reading
// from the current byte and failing with the byte where the input stopped making sense.
#include "commands/json_value.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "render/decimal_text.h"

namespace oasis {
namespace {

class Parser {
public:
    Parser(const std::string& text, int maxDepth, size_t maxValues) : text_(text), maxDepth_(maxDepth), maxValues_(maxValues) {}

    bool parseDocument(JsonValue& value, std::string& error) {
        skipSpace();
        bool ok = parseValue(value, 0);
        if (ok) {
            skipSpace();
            if (at_ < text_.size()) ok = fail("unexpected text after the JSON value");
        }
        if (!ok) error = where() + ": " + problem_;
        return ok;
    }

private:
    const std::string& text_;
    const int maxDepth_;
    const size_t maxValues_;
    size_t at_ = 0;
    size_t values_ = 0;
    std::string problem_;

    bool fail(const std::string& problem) {
        problem_ = problem;
        return false;
    }
    bool atEnd() const { return at_ >= text_.size(); }
    char peek() const { return atEnd() ? '\0' : text_[at_]; }
    bool consume(char c) {
        if (atEnd() || text_[at_] != c) return false;
        ++at_;
        return true;
    }

    std::string where() const {
        long line = 1 + long(std::count(text_.begin(), text_.begin() + long(std::min(at_, text_.size())), '\n'));
        return "at byte " + std::to_string(at_) + " (line " + std::to_string(line) + ")";
    }

    // What the parser found instead of what it wanted, in words ("the end of the input", "'x'", "byte 0x01").
    std::string found() const {
        if (atEnd()) return "the end of the input";
        unsigned char c = static_cast<unsigned char>(text_[at_]);
        if (c < 0x20 || c >= 0x7f) {
            char hex[8];
            std::snprintf(hex, sizeof(hex), "0x%02x", c);
            return std::string("byte ") + hex;
        }
        return std::string("'") + char(c) + "'";
    }

    void skipSpace() {
        while (!atEnd() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r')) ++at_;
    }

    bool parseValue(JsonValue& value, int depth) {
        if (++values_ > maxValues_) return fail("more than " + std::to_string(maxValues_) + " values");
        switch (peek()) {
            case '{': return parseObject(value, depth + 1);
            case '[': return parseArray(value, depth + 1);
            case '"': value.kind = JsonValue::Kind::String; return parseString(value.text);
            case 't': value.kind = JsonValue::Kind::Bool; value.boolean = true; return parseWord("true");
            case 'f': value.kind = JsonValue::Kind::Bool; value.boolean = false; return parseWord("false");
            case 'n': value.kind = JsonValue::Kind::Null; return parseWord("null");
            default:
                if (peek() == '-' || (peek() >= '0' && peek() <= '9')) return parseNumber(value);
                return fail("expected a value (object, array, string, number, true, false or null), found " + found());
        }
    }

    bool parseWord(const char* word) {
        std::string expected(word);
        if (text_.compare(at_, expected.size(), expected) != 0) return fail("expected '" + expected + "', found " + found());
        at_ += expected.size();
        return true;
    }

    bool enter(int depth) {
        if (depth > maxDepth_) return fail("nesting deeper than " + std::to_string(maxDepth_) + " levels");
        ++at_;  // the opening bracket
        skipSpace();
        return true;
    }

    bool parseObject(JsonValue& value, int depth) {
        value.kind = JsonValue::Kind::Object;
        if (!enter(depth)) return false;
        if (consume('}')) return true;
        for (;;) {
            if (peek() != '"') return fail("expected a member name in double quotes, found " + found());
            value.members.emplace_back();
            if (!parseString(value.members.back().first)) return false;
            skipSpace();
            if (peek() != ':') return fail("expected ':' after a member name, found " + found());
            ++at_;
            skipSpace();
            if (!parseValue(value.members.back().second, depth)) return false;
            skipSpace();
            if (consume('}')) return true;
            if (peek() != ',') return fail("expected ',' or '}' in an object, found " + found());
            ++at_;
            skipSpace();
        }
    }

    bool parseArray(JsonValue& value, int depth) {
        value.kind = JsonValue::Kind::Array;
        if (!enter(depth)) return false;
        if (consume(']')) return true;
        for (;;) {
            value.items.emplace_back();
            if (!parseValue(value.items.back(), depth)) return false;
            skipSpace();
            if (consume(']')) return true;
            if (peek() != ',') return fail("expected ',' or ']' in an array, found " + found());
            ++at_;
            skipSpace();
        }
    }

    // The grammar is checked here (strtod-like readers accept "01", ".5", "1." and "inf"), the value
    // is converted by parseDecimal (render/decimal_text.h), which ignores the locale.
    bool parseNumber(JsonValue& value) {
        size_t start = at_;
        auto digits = [&] {
            size_t first = at_;
            while (!atEnd() && peek() >= '0' && peek() <= '9') ++at_;
            return at_ > first;
        };
        if (peek() == '-') ++at_;
        if (peek() == '0') ++at_;
        else if (!digits()) return fail("expected a digit in a number, found " + found());
        if (peek() == '.') {
            ++at_;
            if (!digits()) return fail("expected a digit after the decimal point, found " + found());
        }
        if (peek() == 'e' || peek() == 'E') {
            ++at_;
            if (peek() == '+' || peek() == '-') ++at_;
            if (!digits()) return fail("expected a digit in the exponent, found " + found());
        }
        if (!atEnd() && peek() >= '0' && peek() <= '9') return fail("a number may not start with 0 followed by digits");
        if (!parseDecimal(std::string_view(text_).substr(start, at_ - start), value.number)) {
            std::string number = text_.substr(start, std::min<size_t>(at_ - start, 40));
            at_ = start;
            return fail("number " + number + " is out of range");
        }
        value.kind = JsonValue::Kind::Number;
        return true;
    }

    bool parseHex4(uint32_t& code) {
        code = 0;
        for (int i = 0; i < 4; ++i, ++at_) {
            char c = peek();
            int digit = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
            if (digit < 0) return fail("expected four hex digits after \\u, found " + found());
            code = code * 16 + uint32_t(digit);
        }
        return true;
    }

    // \uXXXX, or a surrogate pair \uD8XX\uDCXX, into its code point.
    bool parseUnicodeEscape(uint32_t& code) {
        size_t escapeStart = at_ - 2;  // the backslash
        if (!parseHex4(code)) return false;
        auto lone = [&](const char* which) {
            at_ = escapeStart;
            return fail(std::string("lone ") + which + " surrogate in a \\u escape (UTF-16 pairs a high one with a low one)");
        };
        if (code >= 0xDC00 && code <= 0xDFFF) return lone("low");
        if (code < 0xD800 || code > 0xDBFF) return true;
        if (text_.compare(at_, 2, "\\u") != 0) return lone("high");
        at_ += 2;
        uint32_t low = 0;
        if (!parseHex4(low)) return false;
        if (low < 0xDC00 || low > 0xDFFF) return lone("high");
        code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
        return true;
    }

    static void appendUtf8(uint32_t code, std::string& out) {
        if (code < 0x80) {
            out += char(code);
        } else if (code < 0x800) {
            out += char(0xC0 | (code >> 6));
            out += char(0x80 | (code & 0x3F));
        } else if (code < 0x10000) {
            out += char(0xE0 | (code >> 12));
            out += char(0x80 | ((code >> 6) & 0x3F));
            out += char(0x80 | (code & 0x3F));
        } else {
            out += char(0xF0 | (code >> 18));
            out += char(0x80 | ((code >> 12) & 0x3F));
            out += char(0x80 | ((code >> 6) & 0x3F));
            out += char(0x80 | (code & 0x3F));
        }
    }

    bool parseEscape(std::string& out) {
        ++at_;  // the backslash
        if (atEnd()) return fail("string not closed before the end of the input");
        char c = peek();
        ++at_;
        switch (c) {
            case '"': out += '"'; return true;
            case '\\': out += '\\'; return true;
            case '/': out += '/'; return true;
            case 'b': out += '\b'; return true;
            case 'f': out += '\f'; return true;
            case 'n': out += '\n'; return true;
            case 'r': out += '\r'; return true;
            case 't': out += '\t'; return true;
            case 'u': {
                uint32_t code = 0;
                if (!parseUnicodeEscape(code)) return false;
                appendUtf8(code, out);
                return true;
            }
            default:
                --at_;
                return fail("unknown escape in a string: a backslash followed by " + found());
        }
    }

    // Bytes other than escapes are kept as they are: oasis writes UTF-8, and a report's strings are
    // only printed again.
    bool parseString(std::string& out) {
        size_t start = at_;
        ++at_;  // the opening quote
        for (;;) {
            if (atEnd()) {
                at_ = start;
                return fail("string not closed before the end of the input");
            }
            if (consume('"')) return true;
            char c = peek();
            if (static_cast<unsigned char>(c) < 0x20) return fail("control character " + found() + " in a string (it must be escaped)");
            if (c == '\\') {
                if (!parseEscape(out)) return false;
            } else {
                out += c;
                ++at_;
            }
        }
    }
};

}  // namespace

const JsonValue* JsonValue::find(const std::string& key) const {
    if (kind != Kind::Object) return nullptr;
    for (const auto& [name, member] : members)
        if (name == key) return &member;
    return nullptr;
}

bool parseJson(const std::string& text, JsonValue& value, std::string& error, int maxDepth, size_t maxValues) {
    value = JsonValue();
    return Parser(text, maxDepth, maxValues).parseDocument(value, error);
}

}  // namespace oasis
