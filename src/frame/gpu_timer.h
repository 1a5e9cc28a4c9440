// Per-pass GPU time from GL_TIME_ELAPSED queries, and the start-up check that decides whether
// this driver's queries can be trusted.
//
// Some drivers' timer queries do not measure each pass's work: on llvmpipe a whole frame's query
// agrees with wall time, but per pass the deferred rasterisation lands in whichever query is open
// when it happens (a clear reads 40 ms, the terrain 4), while zink's agree with wall time
// (shared/PLATFORM.md). So at start-up oasis times a few frames both ways, per pass: queries as
// they are used (no glFinish between passes) against wall time with a glFinish after each pass,
// and uses the queries only where the two agree; elsewhere passes are timed by wall time with a
// glFinish after each. The clock in use and the reason travel with every timing oasis prints.
#pragma once
#include "stats/timing_stats.h"
#include <epoxy/gl.h>

#include <deque>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace oasis {

class Renderer;
struct SceneSettings;

using PassTimes = std::vector<std::pair<std::string, double>>;  // pass name, milliseconds, in order

struct TimingClock {
    bool gpuTimers = false;  // per-pass times from GL_TIME_ELAPSED; else wall time with glFinish per pass
    double disagreement = 0.0;  // the check's sum over passes of |query - wall|, over the wall sum
    std::string reason;

    std::string name() const { return gpuTimers ? "gpu-timer-query" : "wall-glfinish"; }
    std::string describe() const;  // "GPU timer queries (trusted: ...)" / "wall time around glFinish (...)"
};

// The decision from the check's per-pass medians (the same passes in the same order): the
// queries are trusted when the sum over passes of |query - wall| is at most kTimerDisagreement of
// the wall times' sum (glFinish after each pass costs a little, so they never agree exactly; a
// query that does not measure its pass moves whole passes' time about). Pure, for the unit tests.
inline constexpr double kTimerDisagreement = 0.25;
// ... and no pass's query reads more than 25 % plus 0.5 ms over its wall time: a query longer than
// the glFinish-bracketed pass is another pass's time (llvmpipe's, now that its frame sums agree).
inline constexpr double kTimerOverWall = 0.25;
inline constexpr double kTimerOverWallMs = 0.5;
// The frame with glFinish after every pass: wall milliseconds per pass, in order. The
// synchronisation itself costs a little, so the sum can exceed an unsynchronised frame.
PassTimes renderFrameTimingPasses(Renderer& renderer, const SceneSettings& scene);

TimingClock judgeTimerQueries(const PassTimes& queries, const PassTimes& wall);

// The start-up check: without timer queries (GL_QUERY_COUNTER_BITS 0) the wall clock; else
// `frames` frames of the renderer's active pipeline timed each way, then the judgement.
TimingClock measureTimingClock(Renderer& renderer, const SceneSettings& scene, int frames = 5);

// Each pass's median over frames, in the order the passes first appear.
PassTimes medianPassTimes(const std::vector<PassTimes>& frames);
// Each pass's 95% interval of its median over the frames, in the same order (stats/timing_stats.h).
std::vector<std::pair<std::string, SampleStats>> passSampleStats(const std::vector<PassTimes>& frames);

// Non-stalling per-pass timer: each frame's passes get one query each; a frame's results are read
// only once the driver says they are available (a few frames later), never waited for, except by
// drain(). Frames whose results are still pending when their slot comes round again are dropped.
class PassTimerQueries {
public:
    explicit PassTimerQueries(int framesInFlight = 4);
    // Renders one frame of the renderer's active pipeline with a query around each pass.
    void timeFrame(Renderer& renderer, const SceneSettings& scene);
    // The most recent frame whose results are all available (empty until one is).
    const PassTimes& latest();
    // Every frame read since the last drain (the last kKeptFrames of them) and every pending one,
    // waited for (for a headless run's end), oldest first.
    std::vector<PassTimes> drain();
    static constexpr size_t kKeptFrames = 64;
    int framesDropped() const { return dropped_; }

private:
    // One query name, deleted with its owner (gl/objects.h has no query kind; these never leave here).
    struct Query {
        GLuint name = 0;
        Query();
        ~Query();
        Query(Query&& other) noexcept : name(std::exchange(other.name, 0)) {}
        Query& operator=(Query&& other) noexcept { std::swap(name, other.name); return *this; }
        Query(const Query&) = delete;
        Query& operator=(const Query&) = delete;
    };
    struct PendingFrame {
        std::vector<std::pair<std::string, Query>> passes;
    };
    bool collect(PendingFrame& frame, bool wait, PassTimes& out);
    void collectAvailable();

    int framesInFlight_;
    std::deque<PendingFrame> pending_;
    std::vector<Query> spare_;
    std::deque<PassTimes> read_;  // read, not yet drained
    PassTimes latest_;
    int dropped_ = 0;
};

}  // namespace oasis
