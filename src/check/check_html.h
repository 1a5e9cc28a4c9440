// report.html of `oasis check`: the report (check/check_report.h) as one self-contained page
// that any browser opens from disk: the summary, the driver, the capability table, every case, and
// the images of the failing cases embedded as PNG data: URIs, with a flip between result and reference.
#pragma once
#include <string>
#include <vector>

#include "check/check_report.h"

namespace oasis {

// Besides every failing case, the images of this many passing cases (the first in the report's
// order) are shown, so that the page also shows what a passing frame looks like. The rest stay out:
// three 256x144 PNGs are about 100-200 KB in base64, and a full check has about 35 cases.
constexpr int kPassingCasesWithImages = 2;

// The page's text (UTF-8). Every string from the report is HTML-escaped; the counts are in elements
// with ids count-pass, count-fail and count-skip. Needs no network and no other file.
std::string checkReportHtml(const CheckReport& report);

// `bytes` in base64 (RFC 4648 section 4: A-Z a-z 0-9 + /, padded with '=' to a multiple of 4).
std::string base64Encode(const std::string& bytes);

// `text` with & < > " ' replaced by their entities: safe in an element and in a quoted attribute.
std::string htmlEscape(const std::string& text);

// The command line that reproduces a case: "oasis render " and its options, each quoted for a POSIX
// shell where it needs to be (a b as 'a b', it's as 'it'\''s'). Options whose first is already
// "render" are not given a second one.
std::string renderCommandLine(const std::vector<std::string>& options);

}  // namespace oasis
