// Holds every idle-option rule (cli/option_rules.h) true by rendering its example with the real
// binary: a note's option must change nothing (the PNG's pixels the same as without it: its
// provenance names the options, so the files differ) and the note must be printed; a refusal must
// be exit 2 with its message and no file.
// usage: oasis_option_rules_check OASIS WORK_DIR
#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "cli/option_rules.h"
#include "render/image.h"

namespace {

struct Run {
    int status = -1;
    std::string stderrText;
};

Run runOasis(const std::string& oasis, const std::string& arguments, const std::string& out, const std::string& work) {
    std::string errPath = work + "/stderr.txt";
    std::string command = "'" + oasis + "' render --size 96x54 " + arguments + " --out '" + out + "' > /dev/null 2> '" +
                          errPath + "'";
    Run run;
    int raw = std::system(command.c_str());
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    std::ifstream in(errPath);
    std::stringstream text;
    text << in.rdbuf();
    run.stderrText = text.str();
    return run;
}

std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

// Both PNGs read and their pixels equal.
bool samePixels(const std::string& a, const std::string& b) {
    oasis::Image first, second;
    std::string error;
    return oasis::readPng(a, first, error) && oasis::readPng(b, second, error) && first.width == second.width &&
           first.height == second.height && first.rgba == second.rgba;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: oasis_option_rules_check OASIS WORK_DIR\n");
        return 2;
    }
    std::string oasis = argv[1], work = argv[2];
    std::system(("rm -rf '" + work + "' && mkdir -p '" + work + "'").c_str());
    int failures = 0;
    for (const oasis::OptionRule& rule : oasis::optionRules()) {
        std::string with = work + "/with.png", without = work + "/without.png";
        std::remove(with.c_str());
        std::remove(without.c_str());
        Run run = runOasis(oasis, rule.example, with, work);
        std::string expected = "oasis: --";  // every rule's message names an option
        bool ok = true;
        if (rule.outcome == oasis::RuleOutcome::Refuse) {
            ok = run.status == 2 && run.stderrText.find(expected) != std::string::npos &&
                 fileBytes(with).empty();
        } else {
            Run plain = runOasis(oasis, rule.exampleWithout, without, work);
            std::string note = "oasis: " + std::string(rule.flag);
            ok = run.status == 0 && plain.status == 0 && run.stderrText.find(note) != std::string::npos &&
                 samePixels(with, without);
        }
        std::printf("%s %s: '%s'%s\n", ok ? "ok  " : "FAIL", rule.flag, rule.example,
                    rule.outcome == oasis::RuleOutcome::Refuse ? " refused" : " changes nothing, noted");
        if (!ok) {
            std::printf("     exit %d, stderr:\n%s", run.status, run.stderrText.c_str());
            ++failures;
        }
    }
    std::printf("option rules: %zu rules, %d failures\n", oasis::optionRules().size(), failures);
    return failures ? 1 : 0;
}
