// When an accepted option would do nothing: one table of rules, one row per option and the
// circumstance that makes it idle, so that no option is ever silently ignored. Each row either
// refuses the combination (a usage error, exit 2) or lets it run with a one-line note saying what
// was not done and why. Applied by parseCommandLine after every value has been read.
#pragma once
#include <string>
#include <vector>

namespace oasis {

struct Options;

enum class RuleOutcome { Refuse, Note };

struct OptionRule {
    const char* flag;  // the option that would be idle
    RuleOutcome outcome;
    // Whether the option, as given, is idle in these options (only asked when the flag was given).
    bool (*idle)(const Options& options);
    // The message (for a note: what was not done and why; for a refusal: why and what to do).
    std::string (*why)(const Options& options);
    // A command line (after `oasis render`) where the rule holds, and the same without the option:
    // the tests render both and check the note is true (the same image) or the refusal happens.
    const char* example;
    const char* exampleWithout;
};

const std::vector<OptionRule>& optionRules();

// Applies the rules to the flags given on the command line: a refusal returns false with `error`;
// notes are appended to `notes`.
bool applyOptionRules(const Options& options, std::vector<std::string>& notes, std::string& error);

}  // namespace oasis
