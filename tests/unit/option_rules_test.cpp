// No accepted option is silently ignored (cli/option_rules.h, issue 28): every pair of render's
// options, each with a value that is not its default, is parsed; an accepted pair must carry a
// note for each given option that a rule finds idle, a refused pair must say why; the walk's table
// must cover every option `oasis render --help` lists. The idle combinations issue 28 found are
// pinned one by one. (That each note is true is held by cli.option_rules, which renders them.)
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "cli/option_rules.h"
#include "cli/options.h"

namespace oasis {
namespace {

using Arguments = std::vector<std::string>;

// Every render option with values away from its default (several where the value decides what
// another option does).
const std::vector<Arguments> kRenderOptionValues = {
    {"--size", "96x54"}, {"--size", "8x8"}, {"--time", "30"}, {"--hour", "21"}, {"--camera", "0,20,0,0,-10"},
    {"--reflections", "off"}, {"--reflection-bounds", "off"}, {"--reflection-plant-cull", "on"},
    {"--reflection-plant-cull", "off"}, {"--reflection-resolution", "half"}, {"--shadows", "off"},
    {"--shadow-quality", "high"}, {"--water-level", "2"}, {"--ripples", "0"}, {"--absorption", "0.5"},
    {"--vegetation", "off"}, {"--vegetation-density", "2"}, {"--wind", "0"}, {"--billboards", "whole"},
    {"--tone-map", "separate"}, {"--depth-read", "copy"}, {"--no-compute"}, {"--gl-debug"}, {"--lights", "16"},
    {"--lights-path", "ubo"}, {"--light-method", "tiled"}, {"--force", "no-ssbo"}, {"--api", "gles"},
    {"--workarounds", "all"}, {"--workarounds-file", "/dev/null"}, {"--depth", "reversed-z"}, {"--gbuffer", "full"}, {"--gbuffer", "standard"}, {"--pipeline", "forward"},
    {"--view", "albedo"}, {"--view", "radiance"}, {"--view", "overview"}, {"--view", "stencil"},
    {"--view", "normal-error"}, {"--view-exposure", "2"}, {"--channel", "r"}, {"--range", "0,1"},
    {"--overlay", "negative"}, {"--legend", "off"}, {"--stencil-view", "read-back"}, {"--water-scene", "mirrored"},
    {"--stop-before", "ToneMapPass"}, {"--out", "x.png"}, {"--capture"}, {"--graph"}};

ParseResult parse(const Arguments& a, const Arguments& b) {
    Arguments arguments = {"render"};
    arguments.insert(arguments.end(), a.begin(), a.end());
    arguments.insert(arguments.end(), b.begin(), b.end());
    return parseCommandLine(arguments);
}

bool given(const ParseResult& parsed, const std::string& flag) {
    const auto& flags = parsed.options.givenFlags;
    return std::find(flags.begin(), flags.end(), flag) != flags.end();
}

int notesNaming(const ParseResult& parsed, const std::string& flag) {
    return int(std::count_if(parsed.notes.begin(), parsed.notes.end(),
                             [&](const std::string& note) { return note.rfind(flag + ":", 0) == 0 || note.rfind(flag + " ", 0) == 0; }));
}

TEST(OptionRules, TheWalkCoversEveryRenderOption) {
    std::set<std::string> walked;
    for (const Arguments& value : kRenderOptionValues) walked.insert(value[0]);
    std::string help = usage(Command::Render);
    std::regex flag(R"((^|\s)(--[a-z][a-z-]*))");
    std::set<std::string> listed;
    for (auto it = std::sregex_iterator(help.begin(), help.end(), flag); it != std::sregex_iterator(); ++it)
        listed.insert((*it)[2]);
    for (const std::string& name : listed) {
        if (name == "--help" || walked.count(name)) continue;
        // The help's domain table lists other commands' options too: those render refuses by name.
        ParseResult other = parseCommandLine({"render", name, "1"});
        EXPECT_NE(other.error.find("belongs to"), std::string::npos) << name << " is in render --help but not in the walk";
    }
    for (const OptionRule& rule : optionRules()) EXPECT_TRUE(walked.count(rule.flag)) << rule.flag;
}

// Every pair: accepted with a note for each idle option, or refused with a reason; every rule is met.
TEST(OptionRules, EveryPairIsAppliedOrNotedOrRefused) {
    std::set<std::string> rulesMet;
    int accepted = 0, refused = 0, noted = 0;
    for (size_t i = 0; i < kRenderOptionValues.size(); ++i) {
        for (size_t j = i + 1; j < kRenderOptionValues.size(); ++j) {
            const Arguments &a = kRenderOptionValues[i], &b = kRenderOptionValues[j];
            if (a[0] == b[0]) continue;  // one value per option
            ParseResult parsed = parse(a, b);
            std::string pair = a[0] + " " + (a.size() > 1 ? a[1] : "") + " with " + b[0] + " " + (b.size() > 1 ? b[1] : "");
            if (!parsed.ok) {
                ++refused;
                EXPECT_FALSE(parsed.error.empty()) << pair;
                for (const OptionRule& rule : optionRules())
                    if (parsed.error == rule.why(parsed.options)) rulesMet.insert(rule.flag);
                continue;
            }
            ++accepted;
            for (const OptionRule& rule : optionRules()) {
                bool idleAndGiven = (given(parsed, rule.flag) || std::string(rule.flag) == "--size") && rule.idle(parsed.options);
                ASSERT_FALSE(idleAndGiven && rule.outcome == RuleOutcome::Refuse) << pair << ": accepted, " << rule.flag;
                if (!idleAndGiven) continue;
                EXPECT_EQ(notesNaming(parsed, rule.flag), 1) << pair << ": " << rule.flag << " is idle, no one note";
                rulesMet.insert(rule.flag);
                ++noted;
            }
        }
    }
    for (const OptionRule& rule : optionRules()) EXPECT_TRUE(rulesMet.count(rule.flag)) << rule.flag << " never met";
    std::printf("option pairs: %d accepted (%d notes), %d refused\n", accepted, noted, refused);
    EXPECT_GT(accepted, 500);
}

// The combinations issue 28 found accepted and ignored, one by one.
TEST(OptionRules, TheIssuesIdleCombinationsAreNotedOrRefused) {
    ParseResult cull = parseCommandLine({"render", "--reflection-plant-cull", "on", "--reflection-resolution", "half"});
    ASSERT_TRUE(cull.ok);
    EXPECT_EQ(notesNaming(cull, "--reflection-plant-cull"), 1);
    ParseResult exposure = parseCommandLine({"render", "--view", "final", "--view-exposure", "5"});
    EXPECT_FALSE(exposure.ok);
    EXPECT_NE(exposure.error.find("--view-exposure"), std::string::npos);
    EXPECT_TRUE(parseCommandLine({"render", "--view", "radiance", "--view-exposure", "5"}).ok);
    EXPECT_TRUE(parseCommandLine({"render", "--view", "overview", "--view-exposure", "5"}).ok);
    for (const char* size : {"2x1", "1x1", "16384x1", "1x16384"}) {
        ParseResult overview = parseCommandLine({"render", "--view", "overview", "--size", size});
        EXPECT_FALSE(overview.ok) << size;
        EXPECT_NE(overview.error.find("--view overview needs at least"), std::string::npos) << overview.error;
    }
    EXPECT_TRUE(parseCommandLine({"render", "--view", "overview", "--size", "96x54"}).ok);
    // The main job takes --json and prints compare's JSON (cli.main_job_json runs it).
    ParseResult mainJson = parseCommandLine({"--json"});
    EXPECT_TRUE(mainJson.ok);
    EXPECT_TRUE(mainJson.options.json);
    EXPECT_TRUE(mainJson.notes.empty());
}

}  // namespace
}  // namespace oasis
