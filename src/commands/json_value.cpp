// The strict JSON reader (commands/json_value.h): nlohmann::json::parse with a callback that sees
// every key and value as it is read, to refuse a repeated key, too deep a nesting and too many
// values before the tree grows; then the parsed document copied into JsonValue's tree.
#include "commands/json_value.h"

#include <nlohmann/json.hpp>

#include <set>

#include "io/printable_text.h"

namespace oasis {
namespace {

using Json = nlohmann::ordered_json;  // members kept in the file's order

// Thrown by the callback to stop the parse with oasis's reason.
struct Refusal {
    std::string why;
};

// Copies the parsed document (its depth bounded by the callback), refusing a NUL in a string or key.
bool copyValue(const Json& from, JsonValue& to, std::string& error) {
    switch (from.type()) {
        case Json::value_t::null: to.kind = JsonValue::Kind::Null; return true;
        case Json::value_t::boolean: to.kind = JsonValue::Kind::Bool; to.boolean = from.get<bool>(); return true;
        case Json::value_t::number_integer:
        case Json::value_t::number_unsigned:
        case Json::value_t::number_float: to.kind = JsonValue::Kind::Number; to.number = from.get<double>(); return true;
        case Json::value_t::string:
            to.kind = JsonValue::Kind::String;
            to.text = from.get<std::string>();
            if (to.text.find('\0') != std::string::npos) {
                error = "a string holds a NUL (\\u0000): \"" + printableText(to.text) + "\"";
                return false;
            }
            return true;
        case Json::value_t::array:
            to.kind = JsonValue::Kind::Array;
            to.items.resize(from.size());
            for (size_t i = 0; i < from.size(); ++i)
                if (!copyValue(from[i], to.items[i], error)) return false;
            return true;
        case Json::value_t::object:
            to.kind = JsonValue::Kind::Object;
            for (const auto& [key, member] : from.items()) {
                if (key.find('\0') != std::string::npos) {
                    error = "a key holds a NUL (\\u0000): \"" + printableText(key) + "\"";
                    return false;
                }
                to.members.emplace_back(key, JsonValue{});
                if (!copyValue(member, to.members.back().second, error)) return false;
            }
            return true;
        default: error = "a value of a kind JSON text does not hold"; return false;
    }
}

// "at byte N (line L)" of nlohmann's byte count (1 past the byte it stopped at).
std::string where(const std::string& text, size_t byte) {
    size_t at = byte > 0 ? byte - 1 : 0;
    size_t line = 1;
    for (size_t i = 0; i < at && i < text.size(); ++i) line += text[i] == '\n';
    return "at byte " + std::to_string(at) + " (line " + std::to_string(line) + ")";
}

}  // namespace

const JsonValue* JsonValue::find(const std::string& key) const {
    if (kind != Kind::Object) return nullptr;
    for (const auto& member : members)
        if (member.first == key) return &member.second;
    return nullptr;
}

bool parseJson(const std::string& text, JsonValue& value, std::string& error, int maxDepth, size_t maxValues) {
    // One set of keys per object being read (nlohmann keeps the last of a repeated key silently).
    std::vector<std::set<std::string>> keys;
    size_t values = 0;
    auto callback = [&](int depth, Json::parse_event_t event, Json& parsed) {
        switch (event) {
            case Json::parse_event_t::object_start:
            case Json::parse_event_t::array_start:
                if (depth >= maxDepth) throw Refusal{"nesting deeper than " + std::to_string(maxDepth) + " levels"};
                if (event == Json::parse_event_t::object_start) keys.emplace_back();
                break;
            case Json::parse_event_t::object_end: keys.pop_back(); break;
            case Json::parse_event_t::key: {
                const std::string& key = parsed.get_ref<const std::string&>();
                if (!keys.back().insert(key).second)
                    throw Refusal{"the key '" + printableText(key) + "' appears twice in one object"};
                break;
            }
            default: break;
        }
        bool aValue = event == Json::parse_event_t::object_start || event == Json::parse_event_t::array_start ||
                      event == Json::parse_event_t::value;
        if (aValue && ++values > maxValues)
            throw Refusal{"more than " + std::to_string(maxValues) + " values"};
        return true;
    };
    Json document;
    try {
        document = Json::parse(text, callback, /*allow_exceptions=*/true, /*ignore_comments=*/false);
    } catch (const Refusal& refusal) {
        error = refusal.why;
        return false;
    } catch (const Json::parse_error& e) {
        // nlohmann's message: "[json.exception.parse_error.101] parse error at line 1, column 4: WHAT".
        std::string what = e.what();
        size_t colon = what.find(": ");
        error = where(text, e.byte) + ": " + printableText(colon == std::string::npos ? what : what.substr(colon + 2));
        return false;
    } catch (const Json::exception& e) {
        // A number past a double's range: "[json.exception.out_of_range.406] number overflow parsing '1e400'".
        std::string what = e.what();
        size_t bracket = what.find("] ");
        error = printableText(bracket == std::string::npos ? what : what.substr(bracket + 2));
        return false;
    }
    value = JsonValue{};
    return copyValue(document, value, error);
}

}  // namespace oasis
