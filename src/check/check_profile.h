// The profile `oasis check` proposes for a broken driver: the smallest set of forced fallbacks
// (`--force` names: no-compute, no-ssbo, ... gl33) under which none of the cases that crashed,
// hung or failed does, nor their main paths (what `oasis render` and the main job draw by the
// driver's own choice). Found by re-running those frames, each in a child process, under
// candidates: every single fallback in the table's order, then pairs, then triples.
#pragma once
#include <string>
#include <vector>

#include "check/check_case_judge.h"

namespace oasis {

struct ProposedProfile {
    bool needed = false;   // some case crashed, timed out or failed
    bool found = false;    // a set of fallbacks under which none does
    std::vector<std::string> fallbacks;  // --force names, in the table's order
    int framesTried = 0;   // child renders the search took
    std::string why;       // what was re-run, what each candidate gave (the report's words)
};

// The fallbacks a profile may propose, in the order they are tried (each --force name).
const std::vector<std::string>& profileCandidates();

// Searches for the profile after a run: `cases` the run's cases, `results` their results.
ProposedProfile proposeProfile(CaseJudge& judge, const Options& options, const std::vector<CheckCase>& cases,
                               const std::vector<CaseResult>& results);

// The profile as a workarounds file (gl/driver_workarounds.h's syntax: a line a row, keyed by this
// renderer and release), for --workarounds-file or $OASIS_WORKAROUNDS.
std::string profileFileText(const ProposedProfile& profile, const std::string& renderer, const std::string& glVersion);

}  // namespace oasis
