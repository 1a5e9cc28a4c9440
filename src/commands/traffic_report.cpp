// Formatting the counted traffic for compare's text and JSON (exact names: scripts depend on them).
#include "commands/traffic_report.h"

#include <cstdio>

#include "io/json_text.h"

namespace oasis {
namespace {

std::string format(const char* pattern, double a, double b, double c, double d) {
    char text[160];
    std::snprintf(text, sizeof(text), pattern, a, b, c, d);
    return text;
}

}  // namespace

std::string trafficColumnsHeader() {
    return "  (B/px written, read, fragment invocations/px, B/px of it cleared)";
}

std::string trafficColumns(const FrameTraffic& traffic, const std::string& pass) {
    const PassTraffic* counted = traffic.measured() ? traffic.find(pass) : nullptr;
    if (!counted) return {};
    return format("  %8.2f w %8.2f r %7.3f frag %6.2f clr", traffic.perPixel(counted->bytesWritten),
                  traffic.perPixel(counted->bytesRead), traffic.perPixel(double(counted->invocations)),
                  traffic.perPixel(double(counted->clearedBytes)));
}

std::string trafficSummary(const FrameTraffic& forward, const FrameTraffic& deferred, const FrameTraffic& floor) {
    if (!forward.measured() || !deferred.measured() || !floor.measured()) return {};
    std::string text = "  memory traffic per pixel of the frame (counted by the driver's queries, docs/traffic.md):\n";
    auto line = [&](const char* name, const FrameTraffic& t) {
        char row[256];
        std::snprintf(row, sizeof(row),
                      "    %-8s %8.2f B/px (%.2f written, %.2f read; cleared: %.2f of the frame's targets, %.2f of the "
                      "shadow maps)  %.2fx floor's\n",
                      name, t.bytesPerPixel(), t.perPixel(t.bytesWritten()), t.perPixel(t.bytesRead()),
                      t.clearedBytesPerPixel(), t.clearedElsewhereBytesPerPixel(),
                      floor.bytesPerPixel() > 0.0 ? t.bytesPerPixel() / floor.bytesPerPixel() : 0.0);
        text += row;
    };
    line("forward", forward);
    line("deferred", deferred);
    char row[160];
    std::snprintf(row, sizeof(row), "    %-8s %8.2f B/px (%.2f written, %.2f read)\n", "floor", floor.bytesPerPixel(),
                  floor.perPixel(floor.bytesWritten()), floor.perPixel(floor.bytesRead()));
    text += row;
    text += "    " + describeInvocationCount(deferred) + "\n";
    return text;
}

std::string pipelineTrafficJson(const char* pipeline, const FrameTraffic& traffic) {
    if (!traffic.measured()) return {};
    std::string name = pipeline;
    std::string json = ", \"" + name + "_passes_traffic\": {";
    for (size_t i = 0; i < traffic.passes.size(); ++i) {
        const PassTraffic& pass = traffic.passes[i];
        json += (i ? ", " : "") + jsonString(pass.name) + ": {\"bytes_written_per_pixel\": " +
                jsonNumber(traffic.perPixel(pass.bytesWritten), 6) +
                ", \"bytes_read_per_pixel\": " + jsonNumber(traffic.perPixel(pass.bytesRead), 6) +
                ", \"fragment_invocations_per_pixel\": " + jsonNumber(traffic.perPixel(double(pass.invocations)), 6) +
                ", \"samples_per_pixel\": " + jsonNumber(traffic.perPixel(double(pass.samples)), 6) +
                ", \"cleared_bytes_per_pixel\": " + jsonNumber(traffic.perPixel(double(pass.clearedBytes)), 6) +
                ", \"samples_uncounted\": " + std::to_string(pass.samplesUncounted) + "}";
    }
    json += "}, \"" + name + "_bytes_per_pixel\": " + jsonNumber(traffic.bytesPerPixel(), 6) + ", \"" + name +
            "_cleared_bytes_per_pixel\": " + jsonNumber(traffic.clearedBytesPerPixel(), 6) + ", \"" + name +
            "_cleared_elsewhere_bytes_per_pixel\": " + jsonNumber(traffic.clearedElsewhereBytesPerPixel(), 6);
    return json;
}

std::string floorTrafficJson(const FrameTraffic& floor) {
    if (!floor.measured()) return {};
    return ", \"floor_bytes_per_pixel\": " + jsonNumber(floor.bytesPerPixel(), 6) +
           ", \"traffic_invocations\": " + jsonString(describeInvocationCount(floor));
}

std::string targetMemoryJson(double forwardBytes, double deferredBytes) {
    char text[128];
    std::snprintf(text, sizeof(text), ", \"target_memory_bytes\": {\"forward\": %.0f, \"deferred\": %.0f}",
                  forwardBytes, deferredBytes);
    return text;
}

}  // namespace oasis
