// The one strict JSON reader of oasis (report.json read back by `oasis check --diff`, the web page's
// arguments): nlohmann's parser (Debian's nlohmann-json3-dev) into a small tree of values, with what
// RFC 8259 leaves open decided strictly: a key twice in one object, a NUL in a string, nesting
// deeper than a limit and more values than a limit are errors, not a silent choice.
#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace oasis {

struct JsonValue {
    enum class Kind { Null, Bool, Number, String, Array, Object };
    Kind kind = Kind::Null;
    bool boolean = false;
    double number = 0.0;
    std::string text;                                        // a String's bytes (UTF-8, escapes decoded)
    std::vector<JsonValue> items;                            // an Array's elements
    std::vector<std::pair<std::string, JsonValue>> members;  // an Object's members, in the file's order

    bool isNull() const { return kind == Kind::Null; }
    bool isNumber() const { return kind == Kind::Number; }
    bool isString() const { return kind == Kind::String; }
    bool isObject() const { return kind == Kind::Object; }
    bool isArray() const { return kind == Kind::Array; }
    // An Object's member named `key` (the parser refuses a key twice); nullptr if there is none or
    // this is not an Object.
    const JsonValue* find(const std::string& key) const;
};

// Deep enough for any report oasis writes (report.json nests four levels), shallow enough that a
// hostile file of "[[[[..." cannot exhaust the stack.
constexpr int kJsonMaxDepth = 64;
// A report has hundreds of values; each costs about 100 bytes parsed, so a hostile file of
// "[[],[],..." (3 bytes a value) could otherwise turn 64 MiB into several GiB.
constexpr size_t kJsonMaxValues = 1000000;

// Parses `text` whole (one value, surrounded by nothing but white space) into `value`. On bad input
// returns false with `error` = "at byte N (line L): WHAT" (nlohmann's reason, escaped: it may quote
// the input) or "the key 'K' appears twice in one object", "a string holds a NUL (\u0000)",
// "nesting deeper than `maxDepth` levels", "more than `maxValues` values" (arrays, objects and
// their members each count one). Invalid UTF-8, control characters, bad escapes and lone
// surrogates, numbers out of a double's range and trailing text are nlohmann's errors.
bool parseJson(const std::string& text, JsonValue& value, std::string& error, int maxDepth = kJsonMaxDepth,
               size_t maxValues = kJsonMaxValues);

}  // namespace oasis
