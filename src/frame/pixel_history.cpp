// The pixel history: one observed frame reads the pixel of every target a pass writes after that
// pass; a pass that left those values unchanged is asked again, in a frame of its own, with its
// draws scissored to the pixel inside an occlusion query (did any sample pass there?).
#include "frame/pixel_history.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "frame/buffer_readback.h"
#include "frame/frame_graph.h"
#include "frame/renderer.h"
#include "gl/objects.h"
#include "passes/pass.h"
#include "render/frame_setup.h"
#include "io/json_text.h"

namespace oasis {
namespace {

struct PixelPlace {
    int glX, glY;  // in the frame's targets, bottom row 0
};

// Where a pass draws this pixel: at the scale it drew at (the reduced reflection's: 1/divisor).
PixelPlace placeOf(const Renderer& renderer, const Pass& pass, PixelPlace place) {
    const int divisor = pass.drawnAtDivisor(renderer.lastFrame().setup);
    return {place.glX / divisor, place.glY / divisor};
}

// What a pass wrote at this pixel: its targets at the scale it drew at (the reduced reflection's
// at 1/divisor, the pixel's texel there).
std::vector<StoredTexel> readWrites(Renderer& renderer, const Pass& pass, PixelPlace place) {
    const FrameTargets& targets = renderer.targets();
    std::vector<StoredTexel> texels;
    for (const Resource& resource : pass.writes(renderer.lastFrame().setup)) {
        Target target;
        int divisor;
        if (!targetOf(resource, target, divisor)) continue;  // buffers have no pixels
        if (targets.layout().stores(target) || target == Target::DepthStencil || target == Target::SceneDepth)
            texels.push_back(readStoredTexel(renderer.parts().shaders, targets, target, place.glX / divisor,
                                            place.glY / divisor,
                                            !renderer.paths().capabilities.depthStencilRead.available, divisor));
    }
    return texels;
}

// Whether a pass changed any of its targets here; false also where what a target held before the
// pass is unknown (no earlier pass of this frame wrote it): the occlusion query then decides.
bool changedKnownValues(const std::vector<StoredTexel>& after, const std::vector<StoredTexel>& before) {
    for (size_t i = 0; i < after.size(); ++i)
        if (!before[i].values.empty() && after[i].values != before[i].values) return true;
    return false;
}

// Why a pass that ran left the pixel alone, as far as the pass's kind and the pixel's stencil say.
std::string whyUntouched(const Pass& pass, int stencilBefore) {
    const std::string name = pass.name();
    if (pass.drawsInReflectionTargets())
        return (stencilBefore & 0x7f) == kStencilWater
                   ? "no sample passed here: nothing of its mirrored draw covers this water pixel (or a nearer one did)"
                   : "stencil test: the mirrored scene is drawn only on water pixels, and this one is not water";
    if (name.rfind("Sky", 0) == 0) return "depth test: a surface covers the pixel, the sky is drawn only where none does";
    if (name.rfind("Lighting", 0) == 0 || name.rfind("LightVolume", 0) == 0)
        return "depth/stencil test: no surface here to light (the sky's pixel), or no light's volume reaches it";
    if (name.rfind("WaterMask", 0) == 0) return "no water here (or the terrain in front of it)";
    return "no sample passed here: nothing of its draw covers the pixel, or a nearer surface won the depth test";
}

// What `pass` (it ran in the last frame) wrote of the buffers that concerns the pixel: its tile's
// light lists. The direct lists with the slice the lighting reads at the pixel's `surface`.
std::vector<BufferAtPixel> buffersAtPixelOf(const Renderer& renderer, const Pass& pass, PixelPlace pixel,
                                            const std::optional<glm::vec3>& surface) {
    std::vector<BufferAtPixel> buffers;
    for (const Resource& resource : pass.writes(renderer.lastFrame().setup)) {
        if (resource != Resource(Buffer::LightTiles)) continue;
        const int divisor = pass.drawnAtDivisor(renderer.lastFrame().setup);
        const PixelPlace place = placeOf(renderer, pass, pixel);
        std::optional<glm::vec3> surfaceHere = pass.reflectionWork() ? std::nullopt : surface;
        if (auto tile = tileAtPixel(pass, place.glX, place.glY, renderer.targets().width(divisor), surfaceHere))
            buffers.push_back(*tile);
    }
    return buffers;
}

}  // namespace

std::vector<double> decodedValues(const StoredTexel& texel) {
    std::vector<double> decoded = texel.values;
    if (texel.format == "RGBA8" || texel.format == "RG8") {
        for (double& v : decoded) v /= 255.0;
    } else if (texel.format == "RG16") {
        for (double& v : decoded) v /= 65535.0;
    } else if (texel.format == "D24S8" && !decoded.empty()) {
        decoded[0] /= 16777215.0;
    }
    return decoded;
}

std::vector<PassAtPixel> pixelHistory(Renderer& renderer, const SceneSettings& scene, int x, int y) {
    const int height = renderer.targets().height();
    if (x < 0 || y < 0 || x >= renderer.targets().width() || y >= height)
        throw std::out_of_range("pixel " + std::to_string(x) + "," + std::to_string(y) + " is outside the frame");
    const PixelPlace pixel{x, height - 1 - y};

    // The values after each pass, in one frame; the stencil before each pass, for the reasons.
    std::map<const Pass*, PassAtPixel> seen;
    std::map<const Pass*, std::vector<StoredTexel>> before;
    std::map<const Pass*, int> stencilBefore;
    std::vector<const Pass*> ran;
    // What a pass's targets held before it: the values the last pass writing each left, read at
    // the same place (the frame's first pass finds them as the frame before left them: unknown).
    std::map<std::string, StoredTexel> current;
    renderer.renderFrame(scene, FrameRequest::observed([&](const Pass& pass) {
        PassAtPixel entry{pass.name(), true, false, "", readWrites(renderer, pass, pixel), {}};
        std::vector<StoredTexel> previous;
        for (const StoredTexel& texel : entry.targets) {
            auto found = current.find(texel.target + (pass.drawsInReflectionTargets() ? "@reflection" : ""));
            previous.push_back(found != current.end() ? found->second : StoredTexel{texel.target, "", "", {}});
        }
        before[&pass] = previous;
        stencilBefore[&pass] = current.count("depth-stencil") ? int(current["depth-stencil"].values.back()) : 0;
        for (const StoredTexel& texel : entry.targets)
            current[texel.target + (pass.drawsInReflectionTargets() ? "@reflection" : "")] = texel;
        seen[&pass] = entry;
        ran.push_back(&pass);
    }));

    // The buffers, once the frame is whole (each is written once a frame, by the pass that owns it;
    // the views' fill draws none) and before the frames below, at the direct scene's surface.
    std::optional<glm::vec3> surface = directSurfaceAt(renderer, pixel.glX, pixel.glY);
    for (const Pass* pass : ran) seen[pass].buffers = buffersAtPixelOf(renderer, *pass, pixel, surface);
    PassAtPixel inputs{kFrameInputsStep, true, false,
                       "the renderer's uploads before the first pass, which the passes read: buffers, no target's pixel",
                       {}, {lightsAtPixel(renderer, surface), plantsAtPixel(renderer)}};

    // Passes whose values did not change (or were unknown before): did their draws touch the pixel at all?
    for (size_t k = 0; k < ran.size(); ++k) {
        const Pass* pass = ran[k];
        PassAtPixel& entry = seen[pass];
        if (entry.targets.empty()) {
            entry.reason = "writes none of the frame's targets (buffers, transform feedback or the shadow maps)";
            continue;
        }
        if (pass->clearsWholeTargets(renderer.lastFrame().setup)) {
            entry.wrote = true;
            entry.reason = "a clear: every pixel of the targets it clears";
            continue;
        }
        if (changedKnownValues(entry.targets, before[pass])) {
            entry.wrote = true;
            entry.reason = "the values changed";
            continue;
        }
        if (pass->name().rfind("WaterMask", 0) == 0) {
            // Its own occlusion query is the frame's (one occlusion query at a time).
            entry.reason = "the values are as they were; whether its draw reached the pixel is not asked (its own "
                           "occlusion query is active then, and one occlusion query runs at a time)";
            continue;
        }
        // A frame of its own: scissor the pixel and count samples from the pass before to this one.
        gl::Query query = gl::createQuery(GL_ANY_SAMPLES_PASSED, "pixel history: " + pass->name() + " at the pixel");
        bool active = false;
        const Pass* previous = k > 0 ? ran[k - 1] : nullptr;
        auto begin = [&]() {
            const PixelPlace place = placeOf(renderer, *pass, pixel);
            glEnable(GL_SCISSOR_TEST);
            glScissor(place.glX, place.glY, 1, 1);
            glBeginQuery(GL_ANY_SAMPLES_PASSED, query.name());
            active = true;
        };
        if (!previous) begin();
        renderer.renderFrame(scene, FrameRequest::observed([&](const Pass& observed) {
            if (&observed == previous) begin();
            if (&observed == pass && active) {
                glEndQuery(GL_ANY_SAMPLES_PASSED);
                glDisable(GL_SCISSOR_TEST);
                active = false;
            }
        }));
        GLuint samples = 0;
        glGetQueryObjectuiv(query.name(), GL_QUERY_RESULT, &samples);
        entry.wrote = samples != 0;
        bool knownBefore = std::all_of(before[pass].begin(), before[pass].end(),
                                       [](const StoredTexel& texel) { return !texel.values.empty(); });
        entry.reason = !entry.wrote   ? whyUntouched(*pass, stencilBefore[pass])
                       : knownBefore ? "wrote the values that were there (a sample passed at the pixel)"
                                     : "a sample passed at the pixel (no earlier pass of the frame wrote these targets)";
    }

    // Every pass of the frame's graph in order (not the views' after it); one that did not run
    // says why (frame/frame_graph.h).
    std::vector<PassAtPixel> history{inputs};
    for (const GraphStep& step : withoutViewSteps(renderer.lastFrame().graph()).steps) {
        auto found = seen.find(step.pass);
        if (found != seen.end()) {
            history.push_back(found->second);
        } else {
            history.push_back({step.pass->name(), false, false,
                               step.culled.empty() ? "did not run this frame" : step.culled, {}, {}});
        }
    }
    return history;
}


std::string historyText(const std::vector<PassAtPixel>& history) {
    std::string text = "history (every pass of the frame, in order):\n";
    for (const PassAtPixel& entry : history) {
        const char* verdict = !entry.ran                      ? "did not run"
                              : entry.wrote                   ? "wrote"
                              : entry.pass == kFrameInputsStep ? "uploaded"
                                                              : "left it";
        char line[512];
        std::snprintf(line, sizeof line, "  %-32s %-12s %s\n", entry.pass.c_str(), verdict, entry.reason.c_str());
        text += line;
        for (const BufferAtPixel& buffer : entry.buffers) text += bufferAtPixelText(buffer);
        if (!entry.wrote) continue;
        for (const StoredTexel& texel : entry.targets) {
            std::snprintf(line, sizeof line, "      %-14s %-8s %s (decoded %s)\n", texel.target.c_str(), texel.format.c_str(),
                          numberList(texel.values, ", ", "%.9g").c_str(),
                          numberList(decodedValues(texel), ", ", "%.6g").c_str());
            text += line;
        }
    }
    return text;
}

std::string historyJson(const std::vector<PassAtPixel>& history) {
    std::string json = "[";
    for (size_t i = 0; i < history.size(); ++i) {
        const PassAtPixel& entry = history[i];
        json += (i ? ", " : "") + std::string("{\"pass\": ") + jsonString(entry.pass) + ", \"ran\": " +
                (entry.ran ? "true" : "false") + ", \"wrote\": " + (entry.wrote ? "true" : "false") +
                ", \"reason\": " + jsonString(entry.reason) + ", \"targets\": {";
        for (size_t t = 0; t < entry.targets.size(); ++t) {
            const StoredTexel& texel = entry.targets[t];
            json += (t ? ", " : "") + jsonString(texel.target) + ": {\"format\": " + jsonString(texel.format) +
                    ", \"stored\": [" + numberList(texel.values, ", ", "%.9g", true) + "], \"decoded\": [" +
                    numberList(decodedValues(texel), ", ", "%.9g", true) + "]}";
        }
        json += "}, \"buffers\": {";
        for (size_t b = 0; b < entry.buffers.size(); ++b)
            json += (b ? ", " : "") + jsonString(entry.buffers[b].buffer) + ": " + bufferAtPixelJson(entry.buffers[b]);
        json += "}}";
    }
    return json + "]";
}

}  // namespace oasis
