// The frame's memory traffic (frame/frame_traffic.h) as compare --passes prints it: columns beside
// each pass's time, a per-frame summary against the floor's, and the JSON keys scripts read.
#pragma once
#include <string>

#include "frame/frame_traffic.h"

namespace oasis {

// "  12.00 w  3.50 r  1.000 frag  4.00 clr" for a pass of the frame ("" when it was not counted).
std::string trafficColumns(const FrameTraffic& traffic, const std::string& pass);
std::string trafficColumnsHeader();
// Lines of the per-frame bytes per pixel of both pipelines against the floor's.
std::string trafficSummary(const FrameTraffic& forward, const FrameTraffic& deferred, const FrameTraffic& floor);
// `, "forward_passes_traffic": {...}, "forward_bytes_per_pixel": ..., "forward_cleared_bytes_per_pixel": ...`
// for `pipeline` "forward" or "deferred"; "" when not counted.
std::string pipelineTrafficJson(const char* pipeline, const FrameTraffic& traffic);
// `, "floor_bytes_per_pixel": ..., "traffic_invocations": "..."`; "" when not counted.
std::string floorTrafficJson(const FrameTraffic& floor);
// `, "target_memory_bytes": {"forward": ..., "deferred": ...}`: the GPU memory of each frame's
// targets as the frame graph allocated them (Renderer::targetMemoryBytes), beside its traffic.
std::string targetMemoryJson(double forwardBytes, double deferredBytes);

}  // namespace oasis
