// compare's and the main job's timing lines and JSON keys (commands/timing_report.h).
#include "commands/timing_report.h"

#include <cstdio>

namespace oasis {
namespace {

// "  forward    178.22 ms/frame [172.52, 185.03] 95% CI, CV 4.2%, no outliers  (15.18x floor
// [14.90, 15.61]; rounds 172.52 to 204.06 ms)": the stream's name padded so the numbers align.
std::string streamLine(const char* name, const SampleStats& s, const std::string& beside) {
    char text[512];
    std::snprintf(text, sizeof(text), "  %-8s %8.2f ms/frame %s %s, CV %.1f%%, %s  (%s; rounds %.2f to %.2f ms)\n",
                  name, s.median, intervalText(s.low, s.high).c_str(), confidenceWords(s).c_str(), 100.0 * s.cv,
                  outlierWords(s).c_str(), beside.c_str(), s.lowest, s.highest);
    return text;
}

std::string overFloor(const RatioStats& r) {
    char text[96];
    if (!r.hasInterval()) std::snprintf(text, sizeof(text), "%.2fx floor, no interval from %d rounds", r.ratio, r.rounds);
    else std::snprintf(text, sizeof(text), "%.2fx floor %s", r.ratio, intervalText(r.low, r.high).c_str());
    return text;
}

}  // namespace

std::string timesText(const PipelineTimes& t, int terrainTriangles) {
    std::string text = streamLine("forward", t.forward, overFloor(t.forwardOverFloorInterval)) +
                       streamLine("deferred", t.deferred, overFloor(t.deferredOverFloorInterval)) +
                       streamLine("floor", t.floor, "full-screen G-buffer write + read");
    text += "  " + describeRatio(t.deferredOverForward, "deferred", "forward") + "\n";
    char line[768];
    std::snprintf(line, sizeof(line),
                  "  %d rounds after %d warm-up frames of each (discarded): a forward frame, a deferred frame and "
                  "the floor in a random order each round (seed %llu; --seed repeats it), wall time around "
                  "glFinish; terrain %d triangles\n",
                  t.rounds, t.warmup, static_cast<unsigned long long>(t.seed), terrainTriangles);
    text += line;
    std::snprintf(line, sizeof(line),
                  "  intervals (95%%): a median's from the order statistics of its rounds, a ratio's from %d "
                  "bootstrap resamples of the paired rounds; x floor = median ms / median floor ms; CV = standard "
                  "deviation / mean; outliers beyond 1.5 (mild) or 3 (severe) IQR of the quartiles\n",
                  kBootstrapResamples);
    text += line;
    double widest = 100.0 * t.widestRelativeHalfWidth();
    if (t.untilCiPercent > 0.0)
        std::snprintf(line, sizeof(line), "  --until-ci %.3g%%: %s after %d rounds (the widest interval, %s's, is "
                      "+-%.1f%% of its median)\n",
                      t.untilCiPercent, t.untilCiReached ? "reached" : "NOT reached at the cap",
                      t.rounds, t.widestStream(), widest);
    else
        std::snprintf(line, sizeof(line), "  precision: the widest interval, %s's, is +-%.1f%% of its median "
                      "(--until-ci PERCENT adds rounds until it is narrower)\n", t.widestStream(), widest);
    text += line;
    return text;
}

std::string timesStatsJson(const PipelineTimes& t) {
    char ci[160];
    std::snprintf(ci, sizeof(ci), "\"forward_over_floor_ci\": [%.4f, %.4f], \"deferred_over_floor_ci\": [%.4f, %.4f], ",
                  t.forwardOverFloorInterval.low, t.forwardOverFloorInterval.high, t.deferredOverFloorInterval.low,
                  t.deferredOverFloorInterval.high);
    std::string json = "\"forward_stats\": " + sampleStatsJson(t.forward, t.warmup) +
                       ", \"deferred_stats\": " + sampleStatsJson(t.deferred, t.warmup) +
                       ", \"floor_stats\": " + sampleStatsJson(t.floor, t.warmup) +
                       ", \"deferred_over_forward\": " + ratioStatsJson(t.deferredOverForward) + ", " + ci +
                       "\"seed\": " + std::to_string(t.seed) + ", \"round_order\": \"random\", ";
    if (t.untilCiPercent > 0.0) {
        char until[128];
        std::snprintf(until, sizeof(until), "\"until_ci\": {\"percent\": %.4g, \"reached\": %s, \"rounds\": %d}, ",
                      t.untilCiPercent, t.untilCiReached ? "true" : "false", t.rounds);
        json += until;
    }
    return json;
}

}  // namespace oasis
