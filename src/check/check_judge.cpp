// The check's image rules and their comparison (check/check_judge.h).
#include "check/check_judge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace oasis {

const std::vector<ImageRule>& imageRules() {
    // Every number here is a measured difference between correct drivers or paths (docs/check.md
    // has the runs); none was widened to let a driver pass.
    static const std::vector<ImageRule> rules = {
        {"identical", 0, 100.0, 0, 0.0,
         "promised: the same maths on the same driver (every light path, plant path, stencil-view path and "
         "the gl33 and ES 3.2 tiers: max abs 0 on llvmpipe in every case of the full check)"},
        {"same-driver-fallback", 1, 60.0, 4, 0.002,
         "a fallback whose maths differs on the same driver: the ES 3.0 tier, without depth clamp, reaches each "
         "shadow cascade's depth towards the sun where desktop clamps (max abs 3 at 1 of 36,864 pixels, 85.1 dB, "
         "at the water pose; flattening the casters per vertex, before, gave max abs 4 at 3 pixels on llvmpipe, 5 "
         "on SwiftShader) and draws its reflection a level apart at a few water pixels: tiled against volume lights"},
        {"same-driver-geometry", 24, 40.0, 255, 0.01,
         "a fallback that draws the same surfaces by other geometry on the same driver: the ES 3.0 tier without "
         "depth clamp finds the water plane per fragment on a full-screen triangle where the main path rasterises "
         "the water's grid, and reaches each shadow cascade's depth towards the sun; SwiftShader in the browser "
         "against its own main path, 6 cases at 256x144: PSNR 42.1 dB at worst, max abs "
         "211 at 5 shore pixels (low sun, stencil view), 1,242 pixels over 1 level and 11 over 24 at the "
         "water pose; llvmpipe max abs 3"},
        {"cross-driver", 24, 30.0, 255, 0.01,
         "another rasteriser against llvmpipe's reference frames (the full check, 256x144): softpipe differs at "
         "plant edges and shadow-compare filtering, at most 325 of 36,864 pixels (0.88%) above 24 levels, PSNR "
         "36.75 dB, max abs 242; zink over lavapipe max abs 3 (84.8 dB); the NVIDIA H100's 1280x720 frame 48.2 dB, "
         "max abs 161 at single plant-edge pixels"},
        {"cross-driver-interior", 8, 0.0, 255, 0.001,
         "another rasteriser at the pixels the case's own geometry calls interior (no silhouette, depth bend, crease, "
         "plant, water outline or shadow edge within a pixel: 38-79% of a shaded frame) against llvmpipe's references, "
         "the mean over those within the level: zink's 30 shaded cases max abs 1, mean within 0.0001 levels; softpipe's "
         "14 (quick and 12, 13, 27, 29, 36, 44) at most 0.038% over 8 (6 pixels), mean -0.021 at worst (its plants' "
         "shadows at the low sun); the bounds 2.6x and 2.4x those. Beyond them: the sky 3% too bright (mean +0.23 to "
         "+0.84), the sun's N.L flipped near 0 (0.76-1.01% over 8 in the day cases)",
         true, 0.05},
    };
    return rules;
}

const ImageRule& imageRule(const std::string& name) {
    for (const ImageRule& rule : imageRules())
        if (rule.name == name) return rule;
    throw std::invalid_argument("no image rule named " + name);
}

namespace {
int pixelDifference(const Image& a, const Image& b, int x, int y) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])));
    return d;
}
}  // namespace

Judgement judge(const Image& result, const Image& reference, const ImageRule& rule) {
    ImageDifference difference = compareImages(result, reference);  // throws on a size mismatch
    Judgement j;
    j.psnrDb = difference.psnrDb;
    j.maxAbs = difference.maxAbs;
    double signedSum = 0;
    for (int y = 0; y < result.height; ++y)
        for (int x = 0; x < result.width; ++x) {
            if (pixelDifference(result, reference, x, y) > rule.level) ++j.pixelsOver;
            for (int c = 0; c < 3; ++c) signedSum += int(result.pixel(x, y)[c]) - int(reference.pixel(x, y)[c]);
        }
    double samples = 3.0 * double(result.width) * double(result.height);
    j.meanSigned = samples > 0 ? signedSum / samples : 0.0;
    long allowed = long(std::floor(rule.maxFractionOver * double(result.width) * double(result.height)));
    j.pass = j.psnrDb >= rule.minPsnrDb && j.maxAbs <= rule.maxAbs && j.pixelsOver <= allowed;
    char text[256];
    std::snprintf(text, sizeof(text), "PSNR %.2f dB, max abs %d, %ld pixels over %d, mean %+.3f levels (rule %s: PSNR >= %.0f, "
                  "max abs <= %d, at most %ld pixels over %d)", j.psnrDb, j.maxAbs, j.pixelsOver, rule.level, j.meanSigned,
                  rule.name.c_str(), rule.minPsnrDb, rule.maxAbs, allowed, rule.level);
    j.summary = text;
    return j;
}

InteriorJudgement judgeInterior(const Image& result, const Image& reference, const std::vector<uint8_t>& classes,
                                const ImageRule& rule) {
    if (result.width != reference.width || result.height != reference.height ||
        classes.size() != size_t(result.width) * size_t(result.height))
        throw std::invalid_argument("judgeInterior: the frames and their classes differ in size");
    InteriorJudgement j;
    double signedSum = 0;
    for (int y = 0; y < result.height; ++y)
        for (int x = 0; x < result.width; ++x) {
            if (classes[size_t(y) * size_t(result.width) + size_t(x)] != 0) continue;
            ++j.pixels;
            int d = pixelDifference(result, reference, x, y);
            j.maxAbs = std::max(j.maxAbs, d);
            // A pixel over the level is the count's to judge; in the mean a handful of them would
            // outweigh a shift of a level over thousands (softpipe's 6 pixels of up to 115 levels
            // at the low sun moved its interior mean by -0.017).
            if (d > rule.level) {
                ++j.pixelsOver;
                continue;
            }
            for (int c = 0; c < 3; ++c) signedSum += int(result.pixel(x, y)[c]) - int(reference.pixel(x, y)[c]);
        }
    long within = j.pixels - j.pixelsOver;
    j.meanSigned = within > 0 ? signedSum / (3.0 * double(within)) : 0.0;
    long allowed = long(std::floor(rule.maxFractionOver * double(j.pixels)));
    j.pass = j.maxAbs <= rule.maxAbs && j.pixelsOver <= allowed && std::fabs(j.meanSigned) <= rule.maxMeanSigned;
    char text[320];
    std::snprintf(text, sizeof(text), "interior %ld of %d pixels: max abs %d, %ld over %d, mean %+.3f levels (rule %s: max abs "
                  "<= %d, at most %ld over %d, mean within +-%.2f)", j.pixels, result.width * result.height, j.maxAbs,
                  j.pixelsOver, rule.level, j.meanSigned, rule.name.c_str(), rule.maxAbs, allowed, rule.level,
                  rule.maxMeanSigned);
    j.summary = text;
    return j;
}

std::string meanShiftNote(const Judgement& judgement) {
    if (std::fabs(judgement.meanSigned) <= kMeanShiftNote) return {};
    char text[200];
    std::snprintf(text, sizeof(text), "its mean signed difference from the reference frame is %+.2f levels, beyond "
                  "the measured drivers' quick checks (%.1f): a term too %s?", judgement.meanSigned, kMeanShiftNote,
                  judgement.meanSigned > 0 ? "bright" : "dark");
    return text;
}

Image errorMask(const Image& result, const Image& reference, const ImageRule& rule) {
    Image mask(result.width, result.height);
    for (int y = 0; y < result.height; ++y)
        for (int x = 0; x < result.width; ++x) {
            uint8_t* out = mask.pixel(x, y);
            const uint8_t* in = reference.pixel(x, y);
            bool over = pixelDifference(result, reference, x, y) > rule.level;
            for (int c = 0; c < 3; ++c) out[c] = over ? (c == 0 ? 255 : 0) : uint8_t(in[c] / 4);
            out[3] = 255;
        }
    return mask;
}

Image interiorErrorMask(const Image& result, const Image& reference, const std::vector<uint8_t>& classes) {
    // Every interior difference shows, not only those above the rule's level: a mean shift is made
    // of one-level ones.
    Image mask(result.width, result.height);
    for (int y = 0; y < result.height; ++y)
        for (int x = 0; x < result.width; ++x) {
            uint8_t* out = mask.pixel(x, y);
            out[3] = 255;
            if (classes[size_t(y) * size_t(result.width) + size_t(x)] != 0) continue;
            int sum = 0;
            for (int c = 0; c < 3; ++c) sum += int(result.pixel(x, y)[c]) - int(reference.pixel(x, y)[c]);
            for (int c = 0; c < 3; ++c) out[c] = uint8_t(reference.pixel(x, y)[c] / 2);
            if (sum > 0) out[0] = 255, out[1] = out[2] = 0;
            if (sum < 0) out[2] = 255, out[0] = out[1] = 0;
        }
    return mask;
}

}  // namespace oasis
