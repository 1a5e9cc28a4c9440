// `oasis probe --history`: what each pass of the frame did at one pixel, in pass order. Every pass
// of the active pipeline is listed: whether it ran, whether it wrote the pixel, why not where oasis
// knows it (inactive this frame, a stencil or depth test, nothing of its draw covering the pixel),
// and the value it left in each target it writes (stored and decoded); what it wrote of the frame's
// buffers that concerns the pixel (frame/pixel_history_buffers.h), and first the buffers the renderer
// uploads before the passes. RenderDoc's pixel history for oasis's own passes, on every tier.
#pragma once
#include <string>
#include <vector>

#include "frame/pixel_history_buffers.h"
#include "frame/pixel_probe.h"

namespace oasis {

class Renderer;
struct SceneSettings;

struct PassAtPixel {
    std::string pass;
    bool ran = false;                 // active this frame
    bool wrote = false;               // it changed, or (by its own draw's samples) touched, the pixel
    std::string reason;               // how that is known, or why it did not write
    std::vector<StoredTexel> targets; // what each target it writes holds after it (ran passes only)
    std::vector<BufferAtPixel> buffers;  // what it wrote of the buffers that concerns the pixel
};

// Renders the scene with the renderer's active pipeline and records, pass by pass, pixel (x, y)
// (0,0 the top-left pixel) of each target a pass writes. A pass whose draw left the values as
// they were is run again in a frame of its own, scissored to the pixel inside an occlusion query,
// to tell "wrote the same value" from "did not touch it". The first entry, kFrameInputsStep (it
// runs, writes no pixel), holds the uploaded buffers: the light list's lights that reach the
// pixel's surface, the plants' instances. Leaves the last frame rendered.
std::vector<PassAtPixel> pixelHistory(Renderer& renderer, const SceneSettings& scene, int x, int y);

// A texel's numbers decoded from their storage: unorm to 0..1, depth to 0..1 (then the stencil).
std::vector<double> decodedValues(const StoredTexel& texel);

std::string historyText(const std::vector<PassAtPixel>& history);
std::string historyJson(const std::vector<PassAtPixel>& history);  // the value of the key "history"

}  // namespace oasis
