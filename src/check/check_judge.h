// How `oasis check` judges a frame: one table of image rules (each with the measurement that set
// it), the comparison they apply (PSNR, max abs, pixels above a level, as dEQP's fuzzy compare and
// Filament's renderdiff do), and the error mask a failure keeps.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "render/image.h"

namespace oasis {

struct ImageRule {
    std::string name;      // "identical", "cross-driver", ...
    int level = 0;         // a pixel "differs" when its largest channel difference exceeds this
    double minPsnrDb = 0;  // over the frame's RGB (100 = identical)
    int maxAbs = 0;        // the largest channel difference allowed anywhere
    double maxFractionOver = 0;  // of the frame's pixels, at most this fraction may differ
    std::string measuredBy;      // the measurement between correct drivers or paths that set it
    // A rule over the frame's interior pixels alone (check/pixel_classes.h: no edge within a pixel),
    // judged by judgeInterior; it also bounds the interior's mean signed difference.
    bool interiorOnly = false;
    double maxMeanSigned = 255.0;  // levels, either sign
};

// The table (docs/check.md prints it): identical, and the rules for what is not promised identical.
const std::vector<ImageRule>& imageRules();
const ImageRule& imageRule(const std::string& name);

struct Judgement {
    bool pass = false;
    double psnrDb = 0;
    int maxAbs = 0;
    long pixelsOver = 0;
    // The mean of result minus reference over every pixel's R, G and B, in levels of 1/255: a
    // shift of the whole frame or of a large part (a term too bright) where rasterisers' edge
    // differences, of either sign, average out. Measured and reported; no rule bounds it yet.
    double meanSigned = 0;
    std::string summary;  // "PSNR 41.2 dB, max abs 38, 12 pixels over 16 (rule cross-driver: ...)"
};
// Throws std::invalid_argument when the sizes differ.
Judgement judge(const Image& result, const Image& reference, const ImageRule& rule);

// A frame against a reference over the pixels `classes` calls interior (0; top row first, as the
// images): how many, their largest channel difference, how many differ above the rule's level,
// and the mean signed difference (result minus reference, R, G and B, in levels) of the others,
// those within the level: a shift, which outliers do not make. A frame with
// no interior pixel passes (nothing there to hold). Throws std::invalid_argument when sizes differ.
struct InteriorJudgement {
    bool pass = false;
    long pixels = 0;  // interior pixels
    int maxAbs = 0;
    long pixelsOver = 0;
    double meanSigned = 0;  // over the interior pixels within the level
    std::string summary;  // "interior 30,112 pixels: max abs 2, 0 over 3, mean +0.412 levels (rule ...)"
};
InteriorJudgement judgeInterior(const Image& result, const Image& reference, const std::vector<uint8_t>& classes,
                                const ImageRule& rule);

// Twice the largest whole-frame mean signed difference of another driver's quick-check frames against
// llvmpipe's references (zink 0.000, softpipe 0.048, SwiftShader 0.041 levels; docs/check.md): beyond
// it lie a sky 3% too bright (up to +0.60) and the sun's N.L flipped near 0 (-0.14). Not a rule:
// softpipe's case 13, outside the quick set, reaches -0.51 over the whole frame (its plants' shadows,
// at edge pixels); the interiors' mean is the rule (cross-driver-interior). A note, pass or fail.
constexpr double kMeanShiftNote = 0.1;
// "its mean signed difference from the reference frame is +0.60 levels, ..." or "" within the note's bound.
std::string meanShiftNote(const Judgement& judgement);

// Red where a pixel differs by more than the rule's level, dark grey copies of the reference elsewhere.
Image errorMask(const Image& result, const Image& reference, const ImageRule& rule);
// For an interior rule's failure, which a shift of a level or two can make: at interior pixels red
// where the result is brighter than the reference (its channels' sum), blue where darker, the
// reference at half brightness where equal; edge pixels black.
Image interiorErrorMask(const Image& result, const Image& reference, const std::vector<uint8_t>& classes);

}  // namespace oasis
