// The statistics of timed samples, GL-free: every time oasis prints (compare, the main job, bench,
// the window's overlay) is a median with a 95% interval, a coefficient of variation and its
// outliers counted by Tukey's fences, and every "faster" is the ratio of two paired medians with a
// bootstrap interval that excludes 1 (issue 44). Tested on synthetic samples with known answers
// in tests/unit/timing_stats_test.cpp.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace oasis {

// The nominal confidence of every interval oasis prints.
inline constexpr double kIntervalConfidence = 0.95;

// The median of the values (the mean of the middle two for an even count; 0 for none).
double median(std::vector<double> values);

// The order-statistic interval for the median: ranks (0-based, into the sorted sample) of the
// lowest and highest value bracketing the median, chosen from the binomial distribution of how
// many samples fall below the true median. Distribution-free and exact for continuous data, no
// random numbers needed; `confidence` is what it really covers: at least `wanted` from 6 samples on,
// below it for 5 or fewer (then the whole range, 1 - 2^(1-n)).
struct MedianInterval {
    int lowRank = 0, highRank = 0;
    double confidence = 0.0;
};
MedianInterval medianIntervalRanks(int count, double wanted = kIntervalConfidence);

// Tukey's fences from the quartiles (linear interpolation between order statistics, R's type 7):
// mild outliers lie beyond 1.5 IQR outside the quartiles but within 3 IQR, severe ones beyond 3 IQR.
struct TukeyFences {
    double q1 = 0.0, q3 = 0.0;
    double mildLow = 0.0, mildHigh = 0.0, severeLow = 0.0, severeHigh = 0.0;
};
TukeyFences tukeyFences(const std::vector<double>& values);
struct OutlierCounts {
    int mild = 0, severe = 0;
};
OutlierCounts countOutliers(const std::vector<double>& values);

// One stream of timed samples (ms) summarised.
struct SampleStats {
    int count = 0;
    double median = 0.0, low = 0.0, high = 0.0;  // the median and its interval
    double confidence = 0.0;                      // what [low, high] covers (medianIntervalRanks)
    double cv = 0.0;                              // sample standard deviation / mean
    double lowest = 0.0, highest = 0.0;
    OutlierCounts outliers;
    // Half the interval's width over the median: what --until-ci compares with its target.
    double relativeHalfWidth() const { return median > 0.0 ? 0.5 * (high - low) / median : 0.0; }
};
SampleStats describeSamples(const std::vector<double>& samples);

// What an interval of a ratio says: below 1 throughout, above 1 throughout, or neither.
enum class SpeedVerdict { Faster, Slower, NoDifference };
const char* verdictName(SpeedVerdict verdict);  // "faster", "slower", "no difference shown" (the JSON's words)

// The ratio of the medians of two paired samples (index i of each timed in the same round) with a
// percentile bootstrap interval: rounds are resampled whole, so what a round shares (the machine's
// load at that moment) stays paired. Seeded, so a run's interval is reproducible.
struct RatioStats {
    double ratio = 0.0, low = 0.0, high = 0.0;
    SpeedVerdict verdict = SpeedVerdict::NoDifference;  // from [low, high] alone: faster when high < 1
    int rounds = 0;
    // Under kMinRoundsForInterval rounds there is no interval (low = high = ratio: resampling one or
    // two rounds spreads nothing) and so no verdict.
    bool hasInterval() const;
};
inline constexpr int kBootstrapResamples = 2000;
// The fewest rounds whose median interval reaches 95% (medianIntervalRanks): below it no ratio
// interval is formed either.
inline constexpr int kMinRoundsForInterval = 6;
RatioStats pairedMedianRatio(const std::vector<double>& numerator, const std::vector<double>& denominator,
                             std::uint64_t seed, int resamples = kBootstrapResamples);

// "178.22 ms [172.52, 185.03] 95% CI, CV 4.2%, outliers 1 mild 0 severe" (or "no outliers").
std::string describeTime(const SampleStats& stats);
// Its parts: "95% CI" (or "only 93% with 5 rounds" where so few cannot cover 95%), and the outliers.
std::string confidenceWords(const SampleStats& stats);
std::string outlierWords(const SampleStats& stats);
// "[0.80, 0.86]"
std::string intervalText(double low, double high);
// The verdict in words, decided by the interval alone: "deferred is faster than forward: 0.83x
// [0.80, 0.86]" or "no difference shown at this noise: deferred/forward 0.97x [0.91, 1.04] — more
// --frames".
std::string describeRatio(const RatioStats& ratio, const std::string& numerator, const std::string& denominator);

// The JSON object `{"median_ms": ..., "ci_ms": [lo, hi], "cv": ..., "outliers": {"mild": m,
// "severe": s}, "rounds": n, "warmup": w}` (compare's forward_stats and the rest).
std::string sampleStatsJson(const SampleStats& stats, int warmup);
// `{"ratio": r, "ci": [lo, hi], "verdict": "faster"}`
std::string ratioStatsJson(const RatioStats& ratio);

}  // namespace oasis
