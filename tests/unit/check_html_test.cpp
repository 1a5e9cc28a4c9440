// Covers src/check/check_html.h: base64 against RFC 4648's vectors, HTML escaping, the command
// line a case prints, and report.html itself: the counts in their ids, every report string escaped,
// nothing fetched from elsewhere, and each shown image a data: URI whose base64 decodes back to
// the PNG of that image (failing cases and the first passing ones only).
#include <gtest/gtest.h>

#include <string>

#include "check/check_html.h"
#include "render/image.h"

namespace oasis {
namespace {

// The inverse of base64Encode, written here from RFC 4648 so the test does not trust the encoder.
std::string base64Decode(const std::string& text) {
    auto value = [](char c) -> int {
        if (c >= 'A' && c <= 'Z') return c - 'A';
        if (c >= 'a' && c <= 'z') return c - 'a' + 26;
        if (c >= '0' && c <= '9') return c - '0' + 52;
        return c == '+' ? 62 : c == '/' ? 63 : -1;
    };
    std::string bytes;
    unsigned bits = 0;
    int count = 0;
    for (char c : text) {
        if (c == '=') break;
        int v = value(c);
        if (v < 0) ADD_FAILURE() << "not base64: " << c;
        bits = (bits << 6) | unsigned(v & 63);
        count += 6;
        if (count >= 8) {
            count -= 8;
            bytes += char((bits >> count) & 0xFF);
        }
    }
    return bytes;
}

size_t occurrences(const std::string& text, const std::string& part) {
    size_t n = 0;
    for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++n;
    return n;
}

Image gradient(int width, int height, int seed) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            uint8_t* p = image.pixel(x, y);
            p[0] = uint8_t(x * 7 + seed), p[1] = uint8_t(y * 13), p[2] = uint8_t(seed * 31), p[3] = 255;
        }
    return image;
}

CaseResult makeCase(const std::string& name, Verdict verdict, bool images) {
    CaseResult c;
    c.name = name;
    c.verdict = verdict;
    c.options = {"--pipeline", "deferred", "--hour", "21.5"};
    c.againstReference.psnrDb = 44.5;
    if (images) {
        c.result = gradient(32, 18, int(name.size()));
        c.reference = gradient(32, 18, 1);
        c.errorMask = gradient(32, 18, 200);
    }
    return c;
}

TEST(CheckHtml, Base64MatchesRfc4648Vectors) {
    EXPECT_EQ(base64Encode(""), "");
    EXPECT_EQ(base64Encode("f"), "Zg==");
    EXPECT_EQ(base64Encode("fo"), "Zm8=");
    EXPECT_EQ(base64Encode("foo"), "Zm9v");
    EXPECT_EQ(base64Encode("foob"), "Zm9vYg==");
    EXPECT_EQ(base64Encode("fooba"), "Zm9vYmE=");
    EXPECT_EQ(base64Encode("foobar"), "Zm9vYmFy");
    EXPECT_EQ(base64Encode(std::string("\xff\xfe\x00", 3)), "//4A");  // high bytes and NUL
    EXPECT_EQ(base64Encode("\x89PNG\r\n\x1a\n"), "iVBORw0KGgo=");   // every PNG's data: URI starts so
    std::string all;
    for (int i = 0; i < 256; ++i) all += char(i);
    for (size_t length = 0; length <= all.size(); length += 37)
        EXPECT_EQ(base64Decode(base64Encode(all.substr(0, length))), all.substr(0, length));
}

TEST(CheckHtml, EscapesTextAndQuotesCommandLines) {
    EXPECT_EQ(htmlEscape("<a href=\"x\">Tom & Jerry's</a>"), "&lt;a href=&quot;x&quot;&gt;Tom &amp; Jerry&#39;s&lt;/a&gt;");
    EXPECT_EQ(renderCommandLine({"--size", "256x144", "--camera", "420,6,160,40,-4"}),
              "oasis render --size 256x144 --camera 420,6,160,40,-4");
    EXPECT_EQ(renderCommandLine({"render", "--out", "my frame.png", "--note", "it's", ""}),
              "oasis render --out 'my frame.png' --note 'it'\\''s' ''");
    EXPECT_EQ(renderCommandLine({}), "oasis render");
}

CheckReport sampleReport() {
    CheckReport report;
    report.oasisVersion = "0.9";
    report.oasisCommit = "abc1234";
    report.vendor = "Mesa";
    report.renderer = "llvmpipe <LLVM & \"friends\">";
    report.glVersion = "4.5 (Core Profile) Mesa 22.3.6";
    report.api = "OpenGL core";
    report.seconds = 12.5;
    report.caps.push_back({"ssbo-light-list", true, false, "forced off: <tier 2>", "forced tier"});
    report.cases.push_back(makeCase("pass-one", Verdict::Pass, true));
    report.cases.push_back(makeCase("fail-<script>alert(1)</script>", Verdict::Fail, true));
    report.cases.push_back(makeCase("pass-two", Verdict::Pass, true));
    report.cases.push_back(makeCase("pass-three", Verdict::Pass, true));  // past kPassingCasesWithImages
    report.cases.push_back(makeCase("skip-one", Verdict::Skip, false));
    report.cases[1].reason = "a & b < c";
    report.cases[1].firstDivergence = FirstDivergence{"LightVolumePass", "Radiance", 77};
    report.cases[4].reason = "no SSBOs: the driver's limit";
    return report;
}

TEST(CheckHtml, CountsAreInTheirIds) {
    std::string html = checkReportHtml(sampleReport());
    EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
    EXPECT_NE(html.find("id=\"count-pass\">3<"), std::string::npos);
    EXPECT_NE(html.find("id=\"count-fail\">1<"), std::string::npos);
    EXPECT_NE(html.find("id=\"count-skip\">1<"), std::string::npos);
    EXPECT_NE(html.find("LightVolumePass &rarr; Radiance (77 px)"), std::string::npos);
    EXPECT_NE(html.find("oasis render --pipeline deferred --hour 21.5"), std::string::npos);
    EXPECT_NE(html.find("0.9 (abc1234)"), std::string::npos);
    EXPECT_NE(html.find(">FAIL</span>"), std::string::npos);
    EXPECT_EQ(html.substr(html.size() - 8), "</html>\n");
}

TEST(CheckHtml, EscapesEveryReportString) {
    std::string html = checkReportHtml(sampleReport());
    EXPECT_EQ(html.find("<script>alert(1)"), std::string::npos);
    EXPECT_NE(html.find("fail-&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
    EXPECT_NE(html.find("llvmpipe &lt;LLVM &amp; &quot;friends&quot;&gt;"), std::string::npos);
    EXPECT_NE(html.find("a &amp; b &lt; c"), std::string::npos);
    EXPECT_NE(html.find("forced off: &lt;tier 2&gt;"), std::string::npos);
    EXPECT_NE(html.find("the driver&#39;s limit"), std::string::npos);
    EXPECT_EQ(occurrences(html, "<script>"), 1u);  // the page's own
}

TEST(CheckHtml, NeedsNoOtherFile) {
    std::string html = checkReportHtml(sampleReport());
    EXPECT_EQ(html.find("http:"), std::string::npos);
    EXPECT_EQ(html.find("https:"), std::string::npos);
    EXPECT_EQ(html.find("<link"), std::string::npos);
    EXPECT_EQ(occurrences(html, "src=\""), occurrences(html, "src=\"data:image/png;base64,"));
}

TEST(CheckHtml, EmbedsTheImagesOfFailingAndFirstPassingCases) {
    CheckReport report = sampleReport();
    std::string html = checkReportHtml(report);
    // pass-one, the failure and pass-two: three images each; pass-three and the skip: none.
    EXPECT_EQ(occurrences(html, "src=\"data:image/png;base64,"), 9u);
    EXPECT_NE(html.find("id=\"images-0\""), std::string::npos);
    EXPECT_NE(html.find("id=\"images-1\""), std::string::npos);
    EXPECT_NE(html.find("id=\"images-2\""), std::string::npos);
    EXPECT_EQ(html.find("id=\"images-3\""), std::string::npos);
    EXPECT_NE(html.find("<a href=\"#images-1\">"), std::string::npos);
    EXPECT_LT(html.find("id=\"images-1\""), html.find("id=\"images-0\""));  // the failure's images first
    EXPECT_NE(html.find("image-rendering: pixelated"), std::string::npos);
    EXPECT_NE(html.find("onclick=\"flip(this)\""), std::string::npos);

    // The failing case's result, reference and mask, in that order, decode to their PNGs.
    size_t at = html.find("id=\"images-1\"");
    for (const Image* image : {&report.cases[1].result, &report.cases[1].reference, &report.cases[1].errorMask}) {
        const std::string prefix = "src=\"data:image/png;base64,";
        at = html.find(prefix, at);
        ASSERT_NE(at, std::string::npos);
        at += prefix.size();
        std::string base64 = html.substr(at, html.find('"', at) - at);
        std::string png;
        ASSERT_TRUE(encodePng(*image, png));
        EXPECT_EQ(base64Decode(base64), png);
        EXPECT_EQ(base64.size() % 4, 0u);
    }
}

TEST(CheckHtml, AReportWithoutImagesOrCasesIsStillAPage) {
    CheckReport report;
    std::string html = checkReportHtml(report);
    EXPECT_NE(html.find("id=\"count-pass\">0<"), std::string::npos);
    EXPECT_NE(html.find("(no case has images)"), std::string::npos);
    EXPECT_NE(html.find("(not reported)"), std::string::npos);
    EXPECT_NE(html.find("NOTHING RAN"), std::string::npos);  // neither PASS nor FAIL without a judged case
}

}  // namespace
}  // namespace oasis
