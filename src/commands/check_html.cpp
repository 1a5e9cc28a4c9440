// report.html (commands/check_html.h): the page is put together from small pieces — the head with
// its style, the summary, the capability table, the case table, one block of images per shown case,
// and a few lines of script for the flip and the zoom — each a function returning its HTML.
#include "commands/check_html.h"

#include <cstdint>
#include <cstdio>

#include "render/decimal_text.h"

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
    html += "<p class=\"counts\"><span>pass <b id=\"count-pass\">" + std::to_string(report.passed()) +
            "</b></span><span>fail <b id=\"count-fail\">" + std::to_string(report.failed()) +
            "</b></span><span>skip <b id=\"count-skip\">" + std::to_string(report.skipped()) + "</b></span><span>of " +
            std::to_string(report.cases.size()) + " cases" + (report.quick ? " (quick)" : "") + "</span></p>\n";
    html += "<table class=\"facts\">\n" + fact("vendor", report.vendor) + fact("renderer", report.renderer) +
            fact("version", report.glVersion) + fact("GLSL", report.glslVersion) + fact("API", report.api) +
            fact("oasis", report.oasisVersion + (report.oasisCommit.empty() ? "" : " (" + report.oasisCommit + ")")) +
            fact("total time", formatNumber("%.1f s", report.seconds)) + "</table>\n</header>\n";
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

// Which cases show their images (check_html.h: every failing one, the first few passing ones).
std::vector<bool> casesWithImages(const CheckReport& report) {
    std::vector<bool> shown(report.cases.size(), false);
    int passing = 0;
    for (size_t i = 0; i < report.cases.size(); ++i) {
        const CaseResult& c = report.cases[i];
        if (c.result.rgba.empty() || c.verdict == Verdict::Skip) continue;
        shown[i] = c.verdict == Verdict::Fail || passing++ < kPassingCasesWithImages;
    }
    return shown;
}

std::string numbers(const CaseResult& c) {
    if (c.verdict == Verdict::Skip) return cell("&mdash;", "number") + cell("&mdash;", "number") + cell("&mdash;", "number");
    return cell(formatNumber("%.2f", c.psnrDb), "number") + cell(std::to_string(c.maxAbs), "number") +
           cell(std::to_string(c.pixelsOver), "number");
}

std::string mainPath(const CaseResult& c) {
    if (!c.mainPathCompared) return cell("&mdash;");
    return cell("<span class=\"nowrap\">" + formatNumber("%.2f dB,", c.mainPathPsnrDb) + "</span> <span class=\"nowrap\">max abs " +
                std::to_string(c.mainPathMaxAbs) + ",</span> <span class=\"nowrap\">" + std::to_string(c.mainPathPixelsOver) +
                " over</span>" +
                (c.mainPathRule.empty() ? "" : "<div class=\"rule\">" + htmlEscape(c.mainPathRule) + "</div>"));
}

std::string divergence(const CaseResult& c) {
    if (!c.firstDivergence) return cell("&mdash;");
    const FirstDivergence& d = *c.firstDivergence;
    return cell(htmlEscape(d.pass) + " &rarr; " + htmlEscape(d.target) + " (" + std::to_string(d.pixels) + " px)");
}

std::string caseTable(const CheckReport& report, const std::vector<bool>& withImages) {
    std::string html = "<h2>Cases</h2>\n<table>\n<tr><th>case</th><th>verdict</th><th>reason</th><th>PSNR dB</th>"
                       "<th>max abs</th><th>pixels over</th><th>main path</th><th>first divergence</th>"
                       "<th>s</th><th>command line</th></tr>\n";
    for (size_t i = 0; i < report.cases.size(); ++i) {
        const CaseResult& c = report.cases[i];
        std::string name = htmlEscape(c.name);
        if (withImages[i]) name = "<a href=\"#images-" + std::to_string(i) + "\">" + name + "</a>";
        std::string reason = htmlEscape(c.reason) +
                             (c.referenceRule.empty() ? "" : "<div class=\"rule\">" + htmlEscape(c.referenceRule) + "</div>");
        html += "<tr>" + cell(name, "name") + cell(verdictSpan(c.verdict)) + cell(reason, "reason") + numbers(c) + mainPath(c) +
                divergence(c) + cell(formatNumber("%.2f", c.seconds), "number") +
                cell("<code class=\"command\">" + htmlEscape(renderCommandLine(c.options)) + "</code>") + "</tr>\n";
    }
    return html + "</table>\n";
}

// One image as an <img> with its PNG inline, at its own size; a note where there is none.
std::string imageFigure(const Image& image, const std::string& cls, const std::string& caption) {
    std::string png;
    std::string body;
    if (image.rgba.empty()) body = "<p>(no image)</p>";
    else if (!encodePng(image, png)) body = "<p>(the image could not be encoded)</p>";
    else
        body = "<img class=\"frame " + cls + "\" width=\"" + std::to_string(image.width) + "\" height=\"" +
               std::to_string(image.height) + "\" alt=\"" + caption + "\" src=\"data:image/png;base64," + base64Encode(png) +
               "\">";
    std::string captionClass = cls == "shown" ? " class=\"shown-caption\"" : "";
    return "<figure>" + body + "<figcaption" + captionClass + ">" + caption + "</figcaption></figure>";
}

std::string caseImages(const CaseResult& c, size_t index) {
    return "<section class=\"case-images\" id=\"images-" + std::to_string(index) + "\">\n<h3>" + verdictSpan(c.verdict) + " " +
           htmlEscape(c.name) + " <button type=\"button\" onclick=\"flip(this)\">flip: show the reference here</button></h3>\n"
           "<div class=\"strip\">" + imageFigure(c.result, "shown", "result") + imageFigure(c.reference, "reference", "reference") +
           imageFigure(c.errorMask, "mask", "error mask") + "</div>\n</section>\n";
}

// The failing cases' images first (what a reader came for), then the passing ones shown for comparison.
std::string imageSections(const CheckReport& report, const std::vector<bool>& withImages) {
    std::string html = "<h2>Images</h2>\n<p>Every failing case, then the first " + std::to_string(kPassingCasesWithImages) +
                       " passing ones; the others can be rendered again with their command line. "
                       "Zoom: <button type=\"button\" onclick=\"zoom(1)\">1&times;</button> "
                       "<button type=\"button\" onclick=\"zoom(2)\">2&times;</button> "
                       "<button type=\"button\" onclick=\"zoom(4)\">4&times;</button> "
                       "<span id=\"images-decoded\" class=\"rule\"></span></p>\n";
    bool any = false;
    for (Verdict verdict : {Verdict::Fail, Verdict::Pass})
        for (size_t i = 0; i < report.cases.size(); ++i) {
            if (!withImages[i] || report.cases[i].verdict != verdict) continue;
            html += caseImages(report.cases[i], i);
            any = true;
        }
    return any ? html : html + "<p>(no case has images)</p>\n";
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
    return pageHead(report) + summary(report) + capabilityTable(report) + caseTable(report, withImages) +
           imageSections(report, withImages) + "<script>" + kScript + "</script>\n</body>\n</html>\n";
}

}  // namespace oasis
