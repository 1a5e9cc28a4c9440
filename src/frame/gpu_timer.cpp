// The timer-query check and the non-stalling per-pass timer.
#include "frame/gpu_timer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

#include "frame/renderer.h"
#include "stats/timing_stats.h"

namespace oasis {
namespace {

bool hasTimerQueries() {
    // OpenGL ES has timer queries only through GL_EXT_disjoint_timer_query (same enums and calls).
    if (!epoxy_is_desktop_gl() && !epoxy_has_gl_extension("GL_EXT_disjoint_timer_query")) return false;
    GLint bits = 0;
    glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &bits);
    return bits > 0;
}

}  // namespace

std::string TimingClock::describe() const {
    return (gpuTimers ? "GPU timer queries (" : "wall time around glFinish (") + reason + ")";
}

PassTimes renderFrameTimingPasses(Renderer& renderer, const SceneSettings& scene) {
    using Clock = std::chrono::steady_clock;
    PassTimes times;
    glFinish();
    Clock::time_point start = Clock::now();
    renderer.renderFrame(scene, FrameRequest::observed([&](const Pass& pass) {
        glFinish();
        Clock::time_point now = Clock::now();
        times.emplace_back(pass.name(), std::chrono::duration<double, std::milli>(now - start).count());
        start = now;
    }));
    return times;
}

TimingClock judgeTimerQueries(const PassTimes& queries, const PassTimes& wall) {
    TimingClock clock;
    if (queries.size() != wall.size() || wall.empty()) {
        clock.reason = "timer queries not trusted: the check timed different passes each way";
        return clock;
    }
    double wallSum = 0.0, querySum = 0.0, apart = 0.0, worst = -1.0;
    size_t worstPass = 0;
    for (size_t i = 0; i < wall.size(); ++i) {
        if (queries[i].first != wall[i].first) {
            clock.reason = "timer queries not trusted: the check timed different passes each way";
            return clock;
        }
        double difference = std::fabs(queries[i].second - wall[i].second);
        wallSum += wall[i].second;
        querySum += queries[i].second;
        apart += difference;
        if (difference > worst) worst = difference, worstPass = i;
    }
    clock.disagreement = wallSum > 0.0 ? apart / wallSum : 1.0;
    // A query can read less than its wall time (the wall holds the CPU's part and the glFinish) but
    // not more: a pass that finished inside its wall time took no longer on the GPU. One that reads
    // more carries another pass's time (llvmpipe, since the frame's sum is close: 25-45 % apart).
    size_t over = wall.size();
    for (size_t i = 0; i < wall.size(); ++i)
        if (queries[i].second > wall[i].second * (1.0 + kTimerOverWall) + kTimerOverWallMs &&
            (over == wall.size() || queries[i].second - wall[i].second > queries[over].second - wall[over].second))
            over = i;
    clock.gpuTimers = clock.disagreement <= kTimerDisagreement && over == wall.size();
    char text[768];
    std::snprintf(text, sizeof(text),
                  "%s: per pass, GL_TIME_ELAPSED (no glFinish between passes) and wall time with a glFinish after each "
                  "differ by %.0f%% of the frame (limit %.0f%%; frame %.3g ms by queries, %.3g ms by wall time; most "
                  "apart: %s, %.3g ms against %.3g ms)",
                  clock.gpuTimers ? "timer queries trusted" : "timer queries not trusted", 100.0 * clock.disagreement,
                  100.0 * kTimerDisagreement, querySum, wallSum, wall[worstPass].first.c_str(),
                  queries[worstPass].second, wall[worstPass].second);
    clock.reason = text;
    if (over != wall.size()) {
        std::snprintf(text, sizeof(text), "; %s's query reads more than its pass took with a glFinish around it (%.3g ms against %.3g ms)",
                      wall[over].first.c_str(), queries[over].second, wall[over].second);
        clock.reason.insert(clock.reason.size() - (clock.reason.back() == ')' ? 1 : 0), text);
    }
    return clock;
}

TimingClock measureTimingClock(Renderer& renderer, const SceneSettings& scene, int frames) {
    if (!hasTimerQueries()) {
        TimingClock clock;
        clock.reason = "this context has no GL_TIME_ELAPSED timer queries (GL_QUERY_COUNTER_BITS is 0)";
        return clock;
    }
    renderer.renderFrame(scene);  // warm-up: programs built, buffers sized
    PassTimerQueries queries(frames + 1);
    for (int i = 0; i < frames; ++i) queries.timeFrame(renderer, scene);
    std::vector<PassTimes> queried = queries.drain(), walled;
    for (int i = 0; i < frames; ++i) walled.push_back(renderFrameTimingPasses(renderer, scene));
    return judgeTimerQueries(medianPassTimes(queried), medianPassTimes(walled));
}

namespace {
// Each pass's milliseconds over the frames, passes in the order they first appear.
std::vector<std::pair<std::string, std::vector<double>>> samplesByPass(const std::vector<PassTimes>& frames) {
    std::vector<std::pair<std::string, std::vector<double>>> byPass;
    std::map<std::string, size_t> index;
    for (const PassTimes& frame : frames)
        for (const auto& [name, ms] : frame) {
            auto [it, added] = index.try_emplace(name, byPass.size());
            if (added) byPass.push_back({name, {}});
            byPass[it->second].second.push_back(ms);
        }
    return byPass;
}
}  // namespace

PassTimes medianPassTimes(const std::vector<PassTimes>& frames) {
    PassTimes medians;
    for (const auto& [name, samples] : samplesByPass(frames)) medians.emplace_back(name, median(samples));
    return medians;
}

std::vector<std::pair<std::string, SampleStats>> passSampleStats(const std::vector<PassTimes>& frames) {
    std::vector<std::pair<std::string, SampleStats>> stats;
    for (const auto& [name, samples] : samplesByPass(frames)) stats.emplace_back(name, describeSamples(samples));
    return stats;
}

PassTimerQueries::Query::Query() { glGenQueries(1, &name); }
PassTimerQueries::Query::~Query() {
    if (name) glDeleteQueries(1, &name);
}

PassTimerQueries::PassTimerQueries(int framesInFlight) : framesInFlight_(std::max(1, framesInFlight)) {}

void PassTimerQueries::timeFrame(Renderer& renderer, const SceneSettings& scene) {
    // Read what has landed first; a frame still pending when the ring is full is given up on,
    // so the caller never waits for the GPU.
    collectAvailable();
    if (int(pending_.size()) >= framesInFlight_) {
        for (auto& [name, query] : pending_.front().passes) spare_.push_back(std::move(query));
        pending_.pop_front();
        ++dropped_;
    }
    PendingFrame frame;
    auto nextQuery = [&] {
        if (spare_.empty()) return Query();
        Query query = std::move(spare_.back());
        spare_.pop_back();
        return query;
    };
    // GL_TIME_ELAPSED queries cannot nest: one runs from the frame's start to the end of the first
    // pass, the next from there to the end of the second, and so on (the gaps are the CPU's).
    Query running = nextQuery();
    glBeginQuery(GL_TIME_ELAPSED, running.name);
    renderer.renderFrame(scene, FrameRequest::observed([&](const Pass& pass) {
        glEndQuery(GL_TIME_ELAPSED);
        frame.passes.emplace_back(pass.name(), std::move(running));
        running = nextQuery();
        glBeginQuery(GL_TIME_ELAPSED, running.name);
    }));
    glEndQuery(GL_TIME_ELAPSED);  // the frame's tail after its last pass: not a pass
    spare_.push_back(std::move(running));
    pending_.push_back(std::move(frame));
}

bool PassTimerQueries::collect(PendingFrame& frame, bool wait, PassTimes& out) {
    if (!wait) {
        // The last query ends last: when it is available, all of the frame's are.
        if (frame.passes.empty()) return true;
        GLuint available = GL_FALSE;
        glGetQueryObjectuiv(frame.passes.back().second.name, GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) return false;
    }
    out.clear();
    for (auto& [name, query] : frame.passes) {
        GLuint64 nanoseconds = 0;
        glGetQueryObjectui64v(query.name, GL_QUERY_RESULT, &nanoseconds);
        out.emplace_back(name, double(nanoseconds) * 1e-6);
        spare_.push_back(std::move(query));
    }
    frame.passes.clear();
    return true;
}

void PassTimerQueries::collectAvailable() {
    PassTimes ready;
    while (!pending_.empty() && collect(pending_.front(), false, ready)) {
        latest_ = ready;
        read_.push_back(ready);
        if (read_.size() > kKeptFrames) read_.pop_front();
        pending_.pop_front();
    }
}

const PassTimes& PassTimerQueries::latest() {
    collectAvailable();
    return latest_;
}

std::vector<PassTimes> PassTimerQueries::drain() {
    std::vector<PassTimes> frames(read_.begin(), read_.end());
    read_.clear();
    for (PendingFrame& frame : pending_) {
        PassTimes times;
        collect(frame, true, times);
        frames.push_back(times);
    }
    pending_.clear();
    if (!frames.empty()) latest_ = frames.back();
    return frames;
}

}  // namespace oasis
