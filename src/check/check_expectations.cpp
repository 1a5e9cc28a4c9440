// The check's expectations file (check/check_expectations.h).
#include "check/check_expectations.h"

#include <fnmatch.h>

#include <regex>
#include <sstream>

namespace oasis {
namespace {

std::string trimmed(const std::string& text) {
    size_t begin = text.find_first_not_of(" \t\r");
    if (begin == std::string::npos) return {};
    size_t end = text.find_last_not_of(" \t\r");
    return text.substr(begin, end - begin + 1);
}

bool knownResult(const std::string& result) {
    for (const char* known : {"fail", "skip", "flake", "crash", "timeout"})
        if (result == known) return true;
    return false;
}

}  // namespace

bool parseExpectations(const std::string& text, std::vector<Expectation>& rules, std::string& error) {
    std::istringstream lines(text);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        auto refuse = [&](const std::string& why) {
            error = "line " + std::to_string(number) + ": " + why;
            return false;
        };
        if (line.find('\0') != std::string::npos) return refuse("a NUL byte");
        Expectation rule;
        rule.line = number;
        size_t hash = line.find('#');
        if (hash != std::string::npos) rule.reason = trimmed(line.substr(hash + 1));
        std::string body = trimmed(line.substr(0, hash));
        if (body.empty()) continue;
        size_t equals = body.rfind('=');
        if (equals == std::string::npos) return refuse("expected 'CASE-GLOB [renderer /REGEX/] = RESULT', got '" + body + "'");
        rule.result = trimmed(body.substr(equals + 1));
        if (!knownResult(rule.result))
            return refuse("the result '" + rule.result + "' is not one of fail, skip, flake, crash, timeout");
        std::string left = trimmed(body.substr(0, equals));
        size_t space = left.find_first_of(" \t");
        rule.glob = left.substr(0, space);
        if (rule.glob.empty()) return refuse("no case glob before '='");
        std::string rest = space == std::string::npos ? "" : trimmed(left.substr(space));
        if (!rest.empty()) {
            const std::string keyword = "renderer";
            if (rest.compare(0, keyword.size(), keyword) != 0)
                return refuse("expected 'renderer /REGEX/' after the glob, got '" + rest + "'");
            std::string pattern = trimmed(rest.substr(keyword.size()));
            if (pattern.size() < 2 || pattern.front() != '/' || pattern.back() != '/')
                return refuse("the renderer's regex is written between slashes: renderer /llvmpipe/");
            rule.rendererRegex = pattern.substr(1, pattern.size() - 2);
            try {
                std::regex check(rule.rendererRegex);
            } catch (const std::regex_error& regexError) {
                return refuse("the regex /" + rule.rendererRegex + "/ does not compile: " + regexError.what());
            }
        }
        rules.push_back(rule);
    }
    return true;
}

std::optional<Expectation> findExpectation(const std::vector<Expectation>& rules, const std::string& caseName,
                                           const std::string& renderer) {
    for (const Expectation& rule : rules) {
        if (fnmatch(rule.glob.c_str(), caseName.c_str(), 0) != 0) continue;
        if (!rule.rendererRegex.empty() && !std::regex_search(renderer, std::regex(rule.rendererRegex))) continue;
        return rule;
    }
    return std::nullopt;
}

}  // namespace oasis
