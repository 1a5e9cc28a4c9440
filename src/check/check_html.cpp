// report.html (check/check_html.h): the page is put together from small pieces — the head with
// its style, the summary, the capability table, the case table, one block of images per shown case,
// and a few lines of script for the flip and the zoom — each a function returning its HTML.
#include "check/check_html.h"

#include <cstdint>
#include <cstdio>

#include "check/oracle_report.h"
#include "io/decimal_text.h"

namespace oasis {
namespace {

// The style sheet: light, legible, the verdicts in colours that also read as text.
const char* kStyle = R"(
body { font: 14px/1.4 system-ui, sans-serif; margin: 1.5em; color: #1d1d1f; background: #fff; }
h1 { font-size: 1.5em; margin: 0 0 .3em; } h2 { font-size: 1.2em; margin: 1.6em 0 .5em; }
table { border-collapse: collapse; margin: .3em 0; }
th, td { border: 1px solid #d0d0d5; padding: .25em .5em; text-align: left; vertical-align: top; }
th { background: #f0f0f3; } td.number { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
td.reason { max-width: 28em; } td.name { white-space: nowrap; } .rule { color: #666; font-size: .85em; }
.nowrap { white-space: nowrap; }
.verdict { font-weight: bold; color: #fff; border-radius: 3px; padding: 0 .4em; }
.pass { background: #2e7d32; } .fail { background: #c62828; } .skip { background: #8d6e00; }
.counts span { display: inline-block; margin-right: 1em; font-size: 1.15em; }
.counts b { font-size: 1.4em; }
.facts th { background: none; border: none; padding: 0 1em 0 0; font-weight: normal; color: #666; }
.facts td { border: none; padding: 0; }
.yes { color: #2e7d32; } .no { color: #c62828; }
code.command { user-select: all; font-size: .85em; background: #f6f6f8; padding: .1em .3em; display: inline-block; max-width: 40em; }
.case-images { margin: 1.2em 0; } .case-images h3 { font-size: 1em; margin: 0 0 .4em; }
.strip { display: flex; gap: 12px; align-items: flex-start; flex-wrap: wrap; }
figure { margin: 0; } figcaption { color: #444; font-size: .9em; }
img.frame { image-rendering: pixelated; border: 1px solid #999; display: block; }
.flipped img.shown { outline: 3px solid #1565c0; }
button { font: inherit; }
.row { display: grid; grid-template-columns: 9.5em minmax(0, 1fr) 8.5em 8.5em 11em 3em; gap: .6em; padding: .2em .3em;
       align-items: baseline; border-bottom: 1px solid #e4e4e8; }
.row.head { font-weight: bold; background: #f0f0f3; } summary.row { cursor: pointer; list-style: none; }
summary.row::-webkit-details-marker { display: none; } details[open] > summary.row { background: #eef3fb; }
.row .name { font-size: .85em; overflow-wrap: anywhere; } .row .c, .row .n { font-variant-numeric: tabular-nums; white-space: nowrap; }
.n { text-align: right; } .detail { padding: .4em 1em 1em; border-bottom: 1px solid #d0d0d5; }
.detail .facts th { white-space: nowrap; vertical-align: top; } pre { margin: 0; white-space: pre-wrap; font-size: .85em; }
.crash, .timeout, .unexpected-pass { background: #6a1b9a; } .flake, .expected-fail { background: #546e7a; }
)";

// The flip shows the reference in the result's place (and back): a difference then blinks where it
// is, which side-by-side images hide. Zoom scales every image by a whole factor, pixels kept sharp.
// On load, the page says how many images the browser decoded (a data: URI it refused shows here).
const char* kScript = R"(
function flip(button) {
  var block = button.closest('.case-images');
  var shown = block.querySelector('img.shown'), reference = block.querySelector('img.reference');
  if (!shown.resultSrc) shown.resultSrc = shown.src;
  var flipped = block.classList.toggle('flipped');
  shown.src = flipped ? reference.src : shown.resultSrc;
  block.querySelector('.shown-caption').textContent = flipped ? 'reference (flipped)' : 'result';
  button.textContent = flipped ? 'flip back to the result' : 'flip: show the reference here';
}
function zoom(factor) {
  document.querySelectorAll('img.frame').forEach(function (img) {
    img.style.width = img.getAttribute('width') * factor + 'px';
    img.style.height = img.getAttribute('height') * factor + 'px';
  });
}
window.addEventListener('load', function () {
  var images = document.querySelectorAll('img.frame'), decoded = 0;
  images.forEach(function (img) { if (img.naturalWidth > 0) decoded++; });
  var note = document.getElementById('images-decoded');
  if (note) note.textContent = decoded + ' of ' + images.length + ' images decoded by this browser';
});
)";

std::string verdictSpan(Verdict verdict) {
    std::string name = verdictName(verdict);
    return "<span class=\"verdict " + name + "\">" + name + "</span>";
}

std::string cell(const std::string& html, const char* cls = nullptr) {
    return std::string("<td") + (cls ? std::string(" class=\"") + cls + "\"" : "") + ">" + html + "</td>";
}

std::string yesNo(bool value) { return value ? "<span class=\"yes\">yes</span>" : "<span class=\"no\">no</span>"; }

std::string pageHead(const CheckReport& report) {
    std::string title = "oasis check: " + std::to_string(report.passed()) + " pass, " + std::to_string(report.failed()) +
                        " fail, " + std::to_string(report.skipped()) + " skip on " + report.renderer;
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + htmlEscape(title) +
           "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
}

std::string fact(const char* name, const std::string& value) {
    return "<tr><th>" + std::string(name) + "</th><td>" + htmlEscape(value.empty() ? "(not reported)" : value) + "</td></tr>\n";
}

std::string summary(const CheckReport& report) {
    // The page's verdict: FAIL if any case failed, PASS if some passed and none failed.
    std::string verdict = report.failed() ? "fail" : report.passed() ? "pass" : "skip";
    std::string label = report.failed() ? "FAIL" : report.passed() ? "PASS" : "NOTHING RAN";
    std::string html = "<header>\n<h1>oasis check <span class=\"verdict " + verdict + "\">" + label + "</span> " +
                       htmlEscape(report.renderer) + "</h1>\n";
    // One count per verdict, each in an element with id count-VERDICT (the tests read them);
    // the rarer verdicts only where a case has them.
    html += "<p class=\"counts\">";
    for (Verdict v : allVerdicts()) {
        int n = report.count(v);
        if (!n && v != Verdict::Pass && v != Verdict::Fail && v != Verdict::Skip) continue;
        html += "<span>" + std::string(verdictName(v)) + " <b id=\"count-" + verdictName(v) + "\">" + std::to_string(n) +
                "</b></span>";
    }
    html += "<span>of " + std::to_string(report.cases.size()) + " cases" + (report.quick ? " (quick)" : "") +
            (report.selection.empty() ? "" : " (" + htmlEscape(report.selection) + ")") + "</span></p>\n";
    html += "<table class=\"facts\">\n" + fact("vendor", report.vendor) + fact("renderer", report.renderer) +
            fact("version", report.glVersion) + fact("GLSL", report.glslVersion) + fact("API", report.api) +
            fact("oasis", report.oasisVersion + (report.oasisCommit.empty() ? "" : " (" + report.oasisCommit + ")")) +
            fact("total time", formatNumber("%.1f s", report.seconds)) +
            fact("cases ran in", report.isolation) +
            fact("reference set", report.referenceDir.empty() ? "" : report.referenceDir + " (" + report.referenceHash + ")");
    if (!report.baselineDir.empty()) html += fact("baseline", report.baselineDir);
    std::string workarounds;
    for (const auto& [name, why] : report.workarounds) workarounds += (workarounds.empty() ? "" : "; ") + name + " (" + why + ")";
    html += fact("workarounds", workarounds.empty() ? "none" : workarounds);
    for (const std::string& note : report.notes) html += fact("note", note);
    html += "</table>\n</header>\n";
    return html;
}

std::string capabilityTable(const CheckReport& report) {
    std::string html = "<h2>Capabilities</h2>\n<table>\n<tr><th>feature</th><th>available</th><th>used</th>"
                       "<th>limited by</th><th>reason</th></tr>\n";
    for (const CapabilityRow& row : report.caps)
        html += "<tr>" + cell(htmlEscape(row.feature)) + cell(yesNo(row.available)) + cell(yesNo(row.used)) +
                cell(htmlEscape(row.limitedBy)) + cell(htmlEscape(row.reason), "reason") + "</tr>\n";
    return html + "</table>\n";
}

// Which cases show their images (check_html.h: every case that did not pass or skip, and the
// first few passing ones).
std::vector<bool> casesWithImages(const CheckReport& report) {
    std::vector<bool> shown(report.cases.size(), false);
    int passing = 0;
    for (size_t i = 0; i < report.cases.size(); ++i) {
        const CaseResult& c = report.cases[i];
        if (c.result.rgba.empty() || c.verdict == Verdict::Skip) continue;
        shown[i] = c.verdict != Verdict::Pass || passing++ < kPassingCasesWithImages;
    }
    return shown;
}

// "41.20 dB, 3" (max abs), with the rule under it; a dash where nothing was compared.
std::string comparison(const FrameComparison& c, const std::string& rule) {
    if (!c.compared) return "<span class=\"c\">&mdash;</span>";
    return "<span class=\"c\" title=\"rule " + htmlEscape(rule) + ": " + std::to_string(c.pixelsOver) +
           " pixels over its level\">" + formatNumber("%.1f dB", c.psnrDb) + " &middot; " + std::to_string(c.maxAbs) + "</span>";
}

// One image as an <img> with its PNG inline, at its own size; nothing where there is none.
std::string imageFigure(const Image& image, const std::string& cls, const std::string& caption) {
    std::string png;
    if (image.rgba.empty() || !encodePng(image, png)) return {};
    std::string captionClass = cls == "shown" ? " class=\"shown-caption\"" : "";
    return "<figure><img class=\"frame " + cls + "\" width=\"" + std::to_string(image.width) + "\" height=\"" +
           std::to_string(image.height) + "\" alt=\"" + caption + "\" src=\"data:image/png;base64," + base64Encode(png) +
           "\"><figcaption" + captionClass + ">" + caption + "</figcaption></figure>";
}

// The case's frames: its result, the frame its mask was computed against (what the flip shows in
// the result's place), the mask beside it, then the other frame.
std::string caseImages(const CaseResult& c, size_t index) {
    bool againstMain = c.maskAgainst == "the main path";
    const Image& compared = againstMain ? c.mainPathImage : c.reference;
    const Image& other = againstMain ? c.reference : c.mainPathImage;
    std::string comparedName = againstMain ? "main path" : "reference";
    std::string html = "<section class=\"case-images\" id=\"images-" + std::to_string(index) + "\">\n<p>" +
                       verdictSpan(c.verdict) + " <button type=\"button\" onclick=\"flip(this)\">flip: show the " +
                       comparedName + " here</button> Zoom: <button type=\"button\" onclick=\"zoom(1)\">1&times;</button> "
                       "<button type=\"button\" onclick=\"zoom(2)\">2&times;</button> "
                       "<button type=\"button\" onclick=\"zoom(4)\">4&times;</button></p>\n<div class=\"strip\">" +
                       imageFigure(c.result, "shown", "result") + imageFigure(compared, "reference", comparedName) +
                       imageFigure(c.errorMask, "mask", "error mask against the " + comparedName) +
                       imageFigure(other, "other", againstMain ? "reference" : "main path") + "</div>\n</section>\n";
    return html;
}

std::string detailLine(const char* name, const std::string& html) {
    return "<tr><th>" + std::string(name) + "</th><td>" + html + "</td></tr>\n";
}

// What a click on a case's line opens: the reason, the three comparisons, the blame, the first
// divergence, what its renderer saw, the reproduce line, a crash's output, the images.
std::string caseDetails(const CaseResult& c, size_t index, bool withImages) {
    auto numbers = [](const FrameComparison& compared, const std::string& rule) {
        if (!compared.compared) return std::string("not compared");
        return formatNumber("%.2f dB", compared.psnrDb) + ", max abs " + std::to_string(compared.maxAbs) + ", " +
               std::to_string(compared.pixelsOver) + " pixels over (rule " + htmlEscape(rule) + ")";
    };
    std::string html = "<div class=\"detail\"><table class=\"facts\">\n" + detailLine("reason", htmlEscape(c.reason));
    html += detailLine("against the reference", numbers(c.againstReference, c.referenceRule));
    html += detailLine("against its main path", numbers(c.againstMainPath, c.mainPathRule));
    html += detailLine("main path against the reference",
                       numbers(c.mainPathAgainstReference, c.referenceRule) +
                           (!c.mainPathAgainstReference.compared ? ""
                            : c.mainPathMatchesReference         ? " &mdash; matches"
                                                                 : " &mdash; differs"));
    if (!c.blame.empty()) html += detailLine("blame", htmlEscape(c.blame));
    if (c.firstDivergence)
        html += detailLine("first divergence", htmlEscape(c.firstDivergence->pass) + " &rarr; " +
                                                   htmlEscape(c.firstDivergence->target) + " (" +
                                                   std::to_string(c.firstDivergence->pixels) + " px)");
    if (c.oracle.ran) html += detailLine("shading oracle", htmlEscape(shadingOracleLine(c.oracle)));
    if (!c.expectation.empty()) html += detailLine("expectation", htmlEscape(c.expectation));
    if (!c.context.renderer.empty())
        html += detailLine("context", htmlEscape((c.context.glVersion.rfind("OpenGL", 0) == 0 ? "" : c.context.api + " ") +
                                                 c.context.glVersion + "; GLSL " + c.context.glslVersion + "; " +
                                                 c.context.renderer));
    html += detailLine("reproduce", "<code class=\"command\">" +
                                        htmlEscape(c.reproduce.empty() ? renderCommandLine(c.options) : c.reproduce) + "</code>");
    if (!c.childTail.empty()) html += detailLine("last output", "<pre>" + htmlEscape(c.childTail) + "</pre>");
    html += "</table>\n";
    if (withImages) html += caseImages(c, index);
    return html + "</div>\n";
}

// One line per case, the cases that need a look first; a click opens the details.
std::string caseList(const CheckReport& report, const std::vector<bool>& withImages) {
    std::string html = "<h2>Cases</h2>\n<p class=\"rule\">One line each, the ones that need a look first; click a "
                       "line for its reason, its three comparisons, its images and the command that draws it. "
                       "Numbers: PSNR &middot; max abs. <span id=\"images-decoded\"></span></p>\n"
                       "<div class=\"row head\"><span>verdict</span><span>case</span><span>vs reference</span>"
                       "<span>vs main path</span><span>blame</span><span class=\"n\">s</span></div>\n";
    std::vector<size_t> order;
    for (int pass = 0; pass < 2; ++pass)
        for (size_t i = 0; i < report.cases.size(); ++i)
            if ((report.cases[i].verdict == Verdict::Pass || report.cases[i].verdict == Verdict::Skip) == (pass == 1))
                order.push_back(i);
    for (size_t i : order) {
        const CaseResult& c = report.cases[i];
        std::string name = htmlEscape(c.name);
        if (withImages[i]) name = "<a href=\"#images-" + std::to_string(i) + "\">" + name + "</a>";
        html += "<details class=\"case\" id=\"case-" + std::to_string(i) + "\"><summary class=\"row\"><span>" +
                verdictSpan(c.verdict) + "</span><span class=\"name\">" + name + "</span>" +
                comparison(c.againstReference, c.referenceRule) +
                comparison(c.againstMainPath, c.mainPathRule) +
                "<span>" + htmlEscape(c.blame) +
                (c.ended.empty() ? "" : "<div class=\"rule\">" + htmlEscape(c.ended) + "</div>") + "</span><span class=\"n\">" +
                formatNumber("%.1f", c.seconds) + "</span></summary>\n" + caseDetails(c, i, withImages[i]) + "</details>\n";
    }
    bool anyImages = false;
    for (bool shown : withImages) anyImages = anyImages || shown;
    if (!anyImages) html += "<p>(no case has images)</p>\n";
    return html;
}

bool needsShellQuotes(const std::string& word) {
    if (word.empty()) return true;
    for (char c : word) {
        bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                     std::string("-_./:=,+%@").find(c) != std::string::npos;
        if (!plain) return true;
    }
    return false;
}

}  // namespace

std::string base64Encode(const std::string& bytes) {
    static const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        // Three bytes (zeros past the end) make 24 bits, written as four 6-bit digits.
        size_t left = bytes.size() - i;
        uint32_t bits = uint32_t(uint8_t(bytes[i])) << 16;
        if (left > 1) bits |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        if (left > 2) bits |= uint32_t(uint8_t(bytes[i + 2]));
        out += kAlphabet[(bits >> 18) & 63];
        out += kAlphabet[(bits >> 12) & 63];
        out += left > 1 ? kAlphabet[(bits >> 6) & 63] : '=';
        out += left > 2 ? kAlphabet[bits & 63] : '=';
    }
    return out;
}

std::string htmlEscape(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string renderCommandLine(const std::vector<std::string>& options) {
    std::string line = "oasis";
    if (options.empty() || options.front() != "render") line += " render";
    for (const std::string& option : options) {
        if (!needsShellQuotes(option)) {
            line += " " + option;
            continue;
        }
        line += " '";
        for (char c : option) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
        line += "'";
    }
    return line;
}

std::string checkReportHtml(const CheckReport& report) {
    std::vector<bool> withImages = casesWithImages(report);
    return pageHead(report) + summary(report) + caseList(report, withImages) + capabilityTable(report) + "<script>" +
           kScript + "</script>\n</body>\n</html>\n";
}

}  // namespace oasis
