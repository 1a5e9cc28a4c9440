// Medians with order-statistic intervals, Tukey's fences and the paired bootstrap of a ratio of
// medians (stats/timing_stats.h); GL-free.
#include "stats/timing_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <stdexcept>

namespace oasis {
namespace {

// P(B = i) for B ~ Binomial(n, 1/2), in log space: n reaches thousands (bench's frames).
double binomialHalfPmf(int n, int i) {
    return std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) - n * std::log(2.0));
}

// The q-quantile by linear interpolation between the order statistics of `sorted` (R's type 7).
double quantile(const std::vector<double>& sorted, double q) {
    double position = q * double(sorted.size() - 1);
    size_t below = size_t(std::floor(position));
    size_t above = std::min(below + 1, sorted.size() - 1);
    return sorted[below] + (position - double(below)) * (sorted[above] - sorted[below]);
}

// The median of values[index[i]] for every i (nth_element: this runs thousands of times a call).
double medianOf(const std::vector<double>& values, const std::vector<size_t>& index, std::vector<double>& scratch) {
    scratch.clear();
    for (size_t i : index) scratch.push_back(values[i]);
    size_t n = scratch.size(), middle = n / 2;
    std::nth_element(scratch.begin(), scratch.begin() + long(middle), scratch.end());
    double upper = scratch[middle];
    if (n % 2) return upper;
    return 0.5 * (upper + *std::max_element(scratch.begin(), scratch.begin() + long(middle)));
}

}  // namespace

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

MedianInterval medianIntervalRanks(int count, double wanted) {
    if (count <= 0) return {};
    // [x_(j), x_(n-j+1)] (1-based) misses the median when j or more samples lie above it or j or
    // more below: coverage 1 - 2 P(B <= j-1). The largest j that still covers `wanted`; j = 1 (the
    // whole range) when none does.
    double below = binomialHalfPmf(count, 0);  // P(B <= j-1), summed as j grows
    MedianInterval interval{0, count - 1, 1.0 - 2.0 * below};
    for (int j = 2; 2 * j <= count + 1; ++j) {
        below += binomialHalfPmf(count, j - 1);
        double coverage = 1.0 - 2.0 * below;
        if (coverage < wanted) break;
        interval = {j - 1, count - j, coverage};
    }
    if (count == 1) interval.confidence = 0.0;  // one sample bounds nothing
    return interval;
}

TukeyFences tukeyFences(const std::vector<double>& values) {
    if (values.empty()) return {};
    std::vector<double> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    TukeyFences fences;
    fences.q1 = quantile(sorted, 0.25);
    fences.q3 = quantile(sorted, 0.75);
    double iqr = fences.q3 - fences.q1;
    fences.mildLow = fences.q1 - 1.5 * iqr, fences.mildHigh = fences.q3 + 1.5 * iqr;
    fences.severeLow = fences.q1 - 3.0 * iqr, fences.severeHigh = fences.q3 + 3.0 * iqr;
    return fences;
}

OutlierCounts countOutliers(const std::vector<double>& values) {
    TukeyFences fences = tukeyFences(values);
    OutlierCounts counts;
    for (double v : values) {
        if (v < fences.severeLow || v > fences.severeHigh) ++counts.severe;
        else if (v < fences.mildLow || v > fences.mildHigh) ++counts.mild;
    }
    return counts;
}

SampleStats describeSamples(const std::vector<double>& samples) {
    SampleStats stats;
    if (samples.empty()) return stats;
    std::vector<double> sorted = samples;
    std::sort(sorted.begin(), sorted.end());
    stats.count = int(sorted.size());
    stats.median = median(sorted);
    MedianInterval interval = medianIntervalRanks(stats.count);
    stats.low = sorted[size_t(interval.lowRank)];
    stats.high = sorted[size_t(interval.highRank)];
    stats.confidence = interval.confidence;
    stats.lowest = sorted.front();
    stats.highest = sorted.back();
    double mean = std::accumulate(sorted.begin(), sorted.end(), 0.0) / double(sorted.size());
    double squares = 0.0;
    for (double v : sorted) squares += (v - mean) * (v - mean);
    stats.cv = sorted.size() > 1 && mean > 0.0 ? std::sqrt(squares / double(sorted.size() - 1)) / mean : 0.0;
    stats.outliers = countOutliers(sorted);
    return stats;
}

bool RatioStats::hasInterval() const { return rounds >= kMinRoundsForInterval; }

const char* verdictName(SpeedVerdict verdict) {
    switch (verdict) {
        case SpeedVerdict::Faster: return "faster";
        case SpeedVerdict::Slower: return "slower";
        case SpeedVerdict::NoDifference: break;
    }
    return "no difference shown";
}

RatioStats pairedMedianRatio(const std::vector<double>& numerator, const std::vector<double>& denominator,
                             std::uint64_t seed, int resamples) {
    if (numerator.empty() || numerator.size() != denominator.size())
        throw std::invalid_argument("pairedMedianRatio: two samples of the same length, at least one each");
    RatioStats result;
    result.ratio = median(numerator) / median(denominator);
    result.low = result.high = result.ratio;
    result.rounds = int(numerator.size());
    if (!result.hasInterval()) return result;  // no interval, no verdict
    // mt19937_64's sequence is fixed by the standard, and the index is taken by modulo (not by a
    // distribution, whose algorithm each library picks), so a seed gives the same interval anywhere.
    std::mt19937_64 random(seed);
    const size_t n = numerator.size();
    std::vector<size_t> index(n);
    std::vector<double> ratios, scratch;
    ratios.reserve(size_t(resamples));
    for (int r = 0; r < resamples; ++r) {
        for (size_t& i : index) i = size_t(random() % n);
        ratios.push_back(medianOf(numerator, index, scratch) / medianOf(denominator, index, scratch));
    }
    std::sort(ratios.begin(), ratios.end());
    double tail = 0.5 * (1.0 - kIntervalConfidence);
    result.low = quantile(ratios, tail);
    result.high = quantile(ratios, 1.0 - tail);
    result.verdict = result.high < 1.0 ? SpeedVerdict::Faster : result.low > 1.0 ? SpeedVerdict::Slower : SpeedVerdict::NoDifference;
    return result;
}

std::string intervalText(double low, double high) {
    // Enough digits that the two ends differ where they do (a 0.2% interval around 12 ms).
    double width = std::fabs(high - low), scale = std::max(std::fabs(low), std::fabs(high));
    int decimals = width > 0.0 && width < 0.05 * scale ? (width < 0.005 * scale ? 4 : 3) : 2;
    char text[96];
    std::snprintf(text, sizeof(text), "[%.*f, %.*f]", decimals, low, decimals, high);
    return text;
}

std::string confidenceWords(const SampleStats& s) {
    if (s.confidence >= kIntervalConfidence - 1e-9) return "95% CI";
    return "only " + std::to_string(int(std::floor(100.0 * s.confidence))) + "% with " + std::to_string(s.count) +
           (s.count == 1 ? " round" : " rounds");
}

std::string outlierWords(const SampleStats& s) {
    if (s.outliers.mild + s.outliers.severe == 0) return "no outliers";
    return "outliers " + std::to_string(s.outliers.mild) + " mild " + std::to_string(s.outliers.severe) + " severe";
}

std::string describeTime(const SampleStats& s) {
    char text[256];
    std::snprintf(text, sizeof(text), "%.2f ms %s %s, CV %.1f%%, %s", s.median, intervalText(s.low, s.high).c_str(),
                  confidenceWords(s).c_str(), 100.0 * s.cv, outlierWords(s).c_str());
    return text;
}

std::string describeRatio(const RatioStats& r, const std::string& numerator, const std::string& denominator) {
    char numbers[128];
    if (!r.hasInterval()) {
        std::snprintf(numbers, sizeof(numbers), "%.2fx", r.ratio);
        return "no verdict from " + std::to_string(r.rounds) + (r.rounds == 1 ? " round" : " rounds") + " (an interval needs " +
               std::to_string(kMinRoundsForInterval) + "): " + numerator + "/" + denominator + " " + numbers +
               " \u2014 more --frames";
    }
    std::snprintf(numbers, sizeof(numbers), "%.2fx %s", r.ratio, intervalText(r.low, r.high).c_str());
    switch (r.verdict) {
        case SpeedVerdict::Faster: return numerator + " is faster than " + denominator + ": " + numbers;
        case SpeedVerdict::Slower: return numerator + " is slower than " + denominator + ": " + numbers;
        case SpeedVerdict::NoDifference: break;
    }
    // The ratio is named here: without a verdict's subject the bare number would not say what it divides.
    return "no difference shown at this noise: " + numerator + "/" + denominator + " " + numbers + " \u2014 more --frames";
}

std::string sampleStatsJson(const SampleStats& s, int warmup) {
    char text[320];
    std::snprintf(text, sizeof(text),
                  "{\"median_ms\": %.4f, \"ci_ms\": [%.4f, %.4f], \"cv\": %.4f, \"outliers\": {\"mild\": %d, "
                  "\"severe\": %d}, \"rounds\": %d, \"warmup\": %d}",
                  s.median, s.low, s.high, s.cv, s.outliers.mild, s.outliers.severe, s.count, warmup);
    return text;
}

std::string ratioStatsJson(const RatioStats& r) {
    char text[160];
    std::snprintf(text, sizeof(text), "{\"ratio\": %.4f, \"ci\": [%.4f, %.4f], \"verdict\": \"%s\"}", r.ratio, r.low,
                  r.high, verdictName(r.verdict));
    return text;
}

}  // namespace oasis
