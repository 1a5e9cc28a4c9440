// The profile the check proposes for a broken driver (check/check_profile.h).
#include "check/check_profile.h"

#include <algorithm>

#include "check/check_references.h"

namespace oasis {
namespace {

bool unexpectedFailure(const CaseResult& result) {
    return (result.verdict == Verdict::Fail || result.verdict == Verdict::Crash || result.verdict == Verdict::Timeout) &&
           result.blame != "the reference set";
}

// ARGUMENTS with the fallbacks added to their --force list (or a --force of their own).
std::vector<std::string> withForced(std::vector<std::string> arguments, const std::vector<std::string>& fallbacks) {
    std::string list;
    for (const std::string& name : fallbacks) list += (list.empty() ? "" : ",") + name;
    auto force = std::find(arguments.begin(), arguments.end(), "--force");
    if (force != arguments.end() && force + 1 != arguments.end()) *(force + 1) += "," + list;
    else arguments.insert(arguments.end(), {"--force", list});
    return arguments;
}

// Every set of `size` candidates, in the table's order.
void setsOfSize(size_t size, size_t from, std::vector<std::string>& chosen, std::vector<std::vector<std::string>>& sets) {
    if (chosen.size() == size) {
        sets.push_back(chosen);
        return;
    }
    for (size_t k = from; k < profileCandidates().size(); ++k) {
        chosen.push_back(profileCandidates()[k]);
        setsOfSize(size, k + 1, chosen, sets);
        chosen.pop_back();
    }
}

}  // namespace

const std::vector<std::string>& profileCandidates() {
    // The fallbacks a desktop driver can be given, the commonest broken feature first (compute
    // and storage buffers are where drivers break most: the seed's AMD story, the softpipe bugs).
    // gles30 is not among them: it needs an OpenGL ES context, a choice of API, not a fallback.
    static const std::vector<std::string> candidates = {"no-compute", "no-ssbo", "no-stencil-texturing",
                                                         "no-depth-clamp", "no-clip-control", "no-read-only-depth",
                                                         "no-dsa", "gl33"};
    return candidates;
}

ProposedProfile proposeProfile(CaseJudge& judge, const Options& options, const std::vector<CheckCase>& cases,
                               const std::vector<CaseResult>& results) {
    ProposedProfile profile;
    struct Trial {
        const CheckCase* c;
        std::vector<std::string> arguments;
        std::string label;
    };
    std::vector<Trial> trials;
    std::vector<std::string> failing;
    for (size_t i = 0; i < cases.size() && i < results.size(); ++i) {
        if (!unexpectedFailure(results[i])) continue;
        failing.push_back(results[i].name.substr(0, 2));
        trials.push_back({&cases[i], results[i].options, results[i].name});
        // The same picture by the driver's own choice: what a plain `oasis render` draws.
        std::vector<std::string> main = checkCaseArguments(cases[i], options, true);
        if (std::none_of(trials.begin(), trials.end(), [&](const Trial& t) { return t.arguments == main; }))
            trials.push_back({&cases[i], main, results[i].name.substr(0, 2) + "'s main path"});
    }
    if (trials.empty()) return profile;
    profile.needed = true;
    std::string cases_;
    for (const std::string& number : failing) cases_ += (cases_.empty() ? "" : ", ") + number;
    profile.why = "re-ran the " + std::to_string(failing.size()) + " cases that crashed, timed out or failed (" + cases_ +
                  ") and their main paths under each candidate";
    for (size_t size = 1; size <= 3 && !profile.found; ++size) {
        std::vector<std::vector<std::string>> sets;
        std::vector<std::string> chosen;
        setsOfSize(size, 0, chosen, sets);
        for (const std::vector<std::string>& set : sets) {
            bool holds = true;
            std::string firstWhy;
            for (const Trial& trial : trials) {
                std::string why;
                ++profile.framesTried;
                if (!judge.frameHolds(*trial.c, withForced(trial.arguments, set), why)) {
                    holds = false;
                    firstWhy = trial.label + " " + why;
                    break;
                }
            }
            std::string name;
            for (const std::string& fallback : set) name += (name.empty() ? "" : ",") + fallback;
            if (holds) {
                profile.found = true;
                profile.fallbacks = set;
                profile.why += "; --force " + name + ": every one renders and matches its reference";
                break;
            }
            if (size == 1) profile.why += "; --force " + name + ": " + firstWhy;
        }
    }
    if (!profile.found) profile.why += "; no set of up to three fallbacks mends them all";
    return profile;
}

std::string profileFileText(const ProposedProfile& profile, const std::string& renderer, const std::string& glVersion) {
    // The renderer and release matched whole, every regex character escaped.
    auto literal = [](const std::string& text) {
        std::string pattern = "^";
        for (char c : text) {
            if (std::string("\\^$.|?*+()[]{}").find(c) != std::string::npos) pattern += '\\';
            pattern += c;
        }
        return pattern + "$";
    };
    std::string release = driverRelease(glVersion);
    std::string text = "# oasis check's proposed workarounds for " + renderer + " (" + glVersion + ")\n# " + profile.why +
                       "\n# apply with: oasis --workarounds-file THIS_FILE ...  (or OASIS_WORKAROUNDS=THIS_FILE)\n";
    for (const std::string& fallback : profile.fallbacks)
        text += "force-" + fallback + " | " + literal(renderer) + " | " + literal(release).substr(1) + "\n";
    return text;
}

}  // namespace oasis
