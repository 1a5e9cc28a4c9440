// Writes report.html (check/check_html.h) for a made-up `oasis check` run, for
// cli.check_html_in_chromium: 3 passing cases, 1 failing case, 2 skipped; the frames are the docs'
// pictures at 256x144 (a check's size), so the page weighs what a real one does. Prints the
// report's counts ("pass 3 fail 1 skip 2") for the test to compare with what the browser shows.
// usage: oasis_check_html_sample OUT.html DOCS_DIR [PASSING FAILING]  (the last two: to weigh pages)
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "check/check_html.h"
#include "io/file_output.h"
#include "render/image.h"

namespace {

using namespace oasis;

// A 1280x720 picture as a 256x144 frame: each output pixel the mean of a 5x5 block.
Image checkSized(const std::string& path) {
    Image full, small(256, 144);
    std::string error;
    if (!readPng(path, full, error) || full.width < 1280 || full.height < 720) {
        std::fprintf(stderr, "check_html_sample: %s\n", error.empty() ? (path + ": smaller than 1280x720").c_str() : error.c_str());
        std::exit(1);
    }
    for (int y = 0; y < small.height; ++y)
        for (int x = 0; x < small.width; ++x)
            for (int channel = 0; channel < 4; ++channel) {
                int sum = 0;
                for (int dy = 0; dy < 5; ++dy)
                    for (int dx = 0; dx < 5; ++dx) sum += full.pixel(x * 5 + dx, y * 5 + dy)[channel];
                small.pixel(x, y)[channel] = uint8_t(sum / 25);
            }
    return small;
}

// The failing frame: the reference with a light missing, a dark patch a reader can find by flipping.
Image withMissingLight(const Image& reference) {
    Image frame = reference;
    for (int y = 70; y < 110; ++y)
        for (int x = 150; x < 210; ++x)
            for (int channel = 0; channel < 3; ++channel) frame.pixel(x, y)[channel] = uint8_t(frame.pixel(x, y)[channel] * 0.55);
    return frame;
}

CaseResult passing(const std::string& name, const Image& frame, std::vector<std::string> options) {
    CaseResult c;
    c.name = name;
    c.verdict = Verdict::Pass;
    c.options = std::move(options);
    c.reason = "within the rule";
    c.referenceRule = "PSNR >= 40 dB, max abs <= 24, pixels over 8 <= 0.5%";
    c.againstReference.psnrDb = 47.31;
    c.againstReference.maxAbs = 9;
    c.againstReference.pixelsOver = 3;
    c.againstMainPath.compared = true;
    c.mainPathRule = "PSNR >= 45 dB against forward";
    c.againstMainPath.psnrDb = 52.8;
    c.againstMainPath.maxAbs = 4;
    c.seconds = 0.84;
    c.result = frame;
    c.reference = frame;
    c.errorMask = differenceHeatmap(frame, frame);
    return c;
}

CaseResult failing(const std::string& name, const Image& reference) {
    CaseResult c;
    c.name = name;
    c.verdict = Verdict::Fail;
    c.options = {"--size", "256x144", "--pipeline", "deferred", "--lights", "64", "--hour", "21.5", "--light-method", "volumes"};
    c.reason = "2400 pixels over the rule's level (0.5% allowed): the point lights' volumes are not lit";
    c.referenceRule = "PSNR >= 40 dB, max abs <= 24, pixels over 8 <= 0.5%";
    c.result = withMissingLight(reference);
    c.reference = reference;
    c.errorMask = differenceHeatmap(c.result, c.reference);
    ImageDifference difference = compareImages(c.result, c.reference);
    c.againstReference.psnrDb = difference.psnrDb;
    c.againstReference.maxAbs = difference.maxAbs;
    c.againstReference.pixelsOver = 2400;
    c.firstDivergence = FirstDivergence{"LightVolumePass", "Radiance", 2400};
    c.seconds = 1.12;
    return c;
}

CaseResult skipped(const std::string& name, const std::string& reason) {
    CaseResult c;
    c.name = name;
    c.verdict = Verdict::Skip;
    c.options = {"--size", "256x144", "--light-list", "ssbo"};
    c.reason = reason;
    return c;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3 && argc != 5) {
        std::fprintf(stderr, "usage: oasis_check_html_sample OUT.html DOCS_DIR [PASSING FAILING]\n");
        return 2;
    }
    std::string docs = argv[2];
    int passingCount = argc == 5 ? std::atoi(argv[3]) : 3, failingCount = argc == 5 ? std::atoi(argv[4]) : 1;
    Image frames[] = {checkSized(docs + "/scene-day.png"), checkSized(docs + "/scene-dusk.png"),
                      checkSized(docs + "/default-deferred.png")};
    Image night = checkSized(docs + "/scene-night.png");

    CheckReport report;
    report.oasisVersion = "0.9.0";
    report.oasisCommit = "168d70a";
    report.vendor = "Mesa";
    report.renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    report.glVersion = "4.5 (Core Profile) Mesa 22.3.6";
    report.glslVersion = "4.50";
    report.api = "OpenGL 4.5 core";
    report.seconds = 41.7;
    report.caps = {{"ssbo-light-list", false, false, "GL_ARB_shader_storage_buffer_object missing", "driver"},
                   {"compute-plant-atlas", true, true, "compute shaders and SSBOs present", ""},
                   {"timer-queries", true, false, "per-pass GL_TIME_ELAPSED differs from wall time by 40% of the frame", "driver"}};
    const char* hours[] = {"10", "18.2", "12"};
    for (int i = 0; i < passingCount; ++i)
        report.cases.push_back(passing("deferred-compact-day-" + std::to_string(i), frames[i % 3],
                                       {"--size", "256x144", "--pipeline", "deferred", "--hour", hours[i % 3]}));
    for (int i = 0; i < failingCount; ++i) report.cases.push_back(failing("deferred-compact-ubo-night-" + std::to_string(i), night));
    report.cases.push_back(skipped("forward-ssbo-lights", "the driver has no SSBOs (GL 4.2): the driver's limit"));
    report.cases.push_back(skipped("deferred-<full>-gbuffer & \"msaa\"", "forced tier gl33: <no> MSAA G-buffer"));

    std::string error;
    if (!writeFileWhole(argv[1], checkReportHtml(report), error)) {
        std::fprintf(stderr, "check_html_sample: %s\n", error.c_str());
        return 1;
    }
    std::printf("pass %d fail %d skip %d\n", report.passed(), report.failed(), report.skipped());
    return 0;
}
