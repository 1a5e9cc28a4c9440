// The frame's memory traffic per pass, counted by the driver: GL_SAMPLES_PASSED and, where the
// context has GL_ARB_pipeline_statistics_query, GL_FRAGMENT_SHADER_INVOCATIONS_ARB around each
// pass, and every glClearBuffer* of the frame sized from its attachments. Bytes follow from the
// passes' declarations (Pass::reads/writes) and the targets' formats (render/gbuffer_layout.h);
// the model and what it ignores are in docs/traffic.md. Unlike times, the counts are the same
// from run to run on one driver.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "frame/pipeline.h"

namespace oasis {

class Renderer;
struct SceneSettings;

struct PassTraffic {
    std::string name;
    uint64_t samples = 0;           // GL_SAMPLES_PASSED over the pass's draws (its own targets' sizes)
    uint64_t invocations = 0;       // fragment-shader invocations (= samples without pipeline statistics)
    uint64_t samplesUncounted = 0;  // invocations while the frame's own occlusion query ran (the water
                                    // mask's GL_ANY_SAMPLES_PASSED shares the binding): counted as samples
    uint64_t clearedBytes = 0;      // bytes of every attachment texel its clears wrote
    uint64_t clearedElsewhere = 0;  // of them, in textures that are not the frame's targets (the
                                    // sun's shadow maps, a reduced reflection's): fixed in size
    double bytesWritten = 0.0;      // samples x declared written targets' texel bytes, plus the clears
    double bytesRead = 0.0;         // invocations x declared read targets' texel bytes
};

struct FrameTraffic {
    std::vector<PassTraffic> passes;  // in the order they ran; a name that ran twice is one entry
    int width = 0, height = 0;
    bool invocationsCounted = false;  // GL_ARB_pipeline_statistics_query answered; else samples stand in
    bool measured() const { return width > 0; }
    double pixels() const { return double(width) * double(height); }
    double perPixel(double value) const { return pixels() > 0.0 ? value / pixels() : 0.0; }
    double bytesWritten() const;
    double bytesRead() const;
    double clearedBytes() const;           // every clear's
    double clearedElsewhereBytes() const;  // of them, the clears of textures other than the frame's targets
    double bytesPerPixel() const { return perPixel(bytesWritten() + bytesRead()); }
    // The clears of the frame's own targets (the G-buffer, depth-stencil, Radiance, Reflection):
    // what issue 30's goal holds against the depth-stencil's bytes.
    double clearedBytesPerPixel() const { return perPixel(clearedBytes() - clearedElsewhereBytes()); }
    double clearedElsewhereBytesPerPixel() const { return perPixel(clearedElsewhereBytes()); }
    const PassTraffic* find(const std::string& name) const;
};

// Whether this context can count samples per pass (desktop GL: GL_SAMPLES_PASSED; OpenGL ES has
// only the boolean occlusion queries), and why not.
bool trafficCountable(std::string* whyNot = nullptr);
// How the fragment invocations were counted, for reports.
std::string describeInvocationCount(const FrameTraffic& traffic);

// One frame of the renderer's active pipeline with the counts around each pass. Renders a frame
// first (programs built), so the counted frame does only the frame's work.
FrameTraffic measureFrameTraffic(Renderer& renderer, const SceneSettings& scene);
// The floor (passes/floor_pass.h) counted the same way: its two full-screen draws, the first
// writing the G-buffer and depth, the second reading the G-buffer into Final, each half its counts.
FrameTraffic measureFloorTraffic(Renderer& renderer);

}  // namespace oasis
