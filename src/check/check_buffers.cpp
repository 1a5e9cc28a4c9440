// Reading back and comparing the buffers of the check's pass-by-pass search (check/check_buffers.h).
#include "check/check_buffers.h"

#include <algorithm>
#include <cmath>

#include "frame/buffer_readback.h"
#include "frame/frame_readback.h"
#include "frame/renderer.h"
#include "passes/light_tiling_pass.h"

namespace oasis {

std::vector<float> lightTileFaults(const std::vector<uint32_t>& tileWords, const std::vector<float>& positions,
                                   const std::vector<float>& lights, int width, int height) {
    std::vector<float> faults(size_t(width) * size_t(height), 0.0f);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            size_t pixel = size_t(y) * size_t(width) + size_t(x);
            const float* p = &positions[pixel * 4];
            if (pixel * 4 + 3 >= positions.size() || p[3] == 0.0f) continue;  // sky: nothing is lit
            size_t base = lightTileOf(x, y, width) * kLightTileWords;
            if (base + kLightTileWords > tileWords.size()) {
                faults[pixel] = float(lights.size() / kLightFloats);  // no list at all for its tile
                continue;
            }
            LightTileWords tile{&tileWords[base]};
            // The slice as common/light_tiles.glsl computes it; within 10^-3 of an edge the compute
            // pass lists the light in both slices, and either may be the one the lighting reads.
            float at = lightSlicePosition(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), tile.nearest(), tile.farthest());
            int slices[3] = {lightSliceOf(at), lightSliceOf(at - 1e-3f), lightSliceOf(at + 1e-3f)};
            bool overflows = false;
            for (int slice : slices) overflows = overflows || tile.count(slice) > OASIS_LIGHT_TILE_MAX_LIGHTS;
            if (overflows) continue;  // the lighting adds every light there
            int missing = 0;
            for (size_t i = 0; i + kLightFloats <= lights.size(); i += kLightFloats) {
                // By more than a part in 10^3 of its radius: the compute pass widens the radius by a
                // part in 10^4, so a light this near the edge is never a fault.
                if (!lightReaches(&lights[i], p, 0.999f)) continue;
                bool found = false;
                for (int slice : slices) found = found || tile.lists(slice, uint32_t(i / kLightFloats));
                missing += !found;
            }
            faults[pixel] = float(missing);
        }
    return faults;
}

void snapshotWrittenBuffers(Renderer& renderer, const Pass& pass, const std::vector<Resource>& written,
                            PassSnapshot& into) {
    for (const Resource& resource : written) {
        const Buffer* buffer = std::get_if<Buffer>(&resource);
        if (!buffer || *buffer != Buffer::LightTiles) continue;
        // A pass that did not run in this path has no lists to check: the other path's check then
        // stands against none missed.
        GLuint tiles = pass.ownBuffer(*buffer);
        if (!tiles || !renderer.lastFrame().graph().runs(pass.name())) continue;
        // The direct half only: the mirrored lists are over the reflection's surfaces, which the
        // frame's targets hold only inside the water (the reflection's own targets when reduced).
        if (pass.reflectionWork()) continue;
        const FrameTargets& targets = renderer.targets();
        int width = targets.width(), height = targets.height();
        std::vector<uint32_t> words = readLightTiles(tiles, 0, LightTilingPass::listBytes(width, height) /
                                                                   (kLightTileWords * sizeof(uint32_t)));
        if (words.empty()) continue;
        into.pixelChecks.push_back({resourceName(*buffer), lightTileFaults(words, readSurfacePositions(renderer),
                                                                           uploadedLights(renderer.lastFrame().setup), width, height)});
    }
}

PassSnapshot snapshotFrameInputs(Renderer& renderer) {
    PassSnapshot snapshot{kFrameInputsStep, {}};
    if (std::vector<float> lights; readLightsAsShadersSee(renderer, lights))
        snapshot.buffers.push_back({resourceName(Buffer::LightList), uint32_t(kLightFloats), false, std::move(lights)});
    // The order of the plants is the placement's, no part of what is drawn.
    snapshot.buffers.push_back(
        {resourceName(Buffer::PlantInstances), uint32_t(plantInstanceFloats()), true, readPlantInstances(renderer)});
    return snapshot;
}

long bufferDifferences(const BufferSnapshot& a, const BufferSnapshot& b, int level) {
    const size_t stride = std::max<size_t>(a.stride, 1);
    auto entries = [&](const BufferSnapshot& snapshot) {
        std::vector<std::vector<float>> list;
        for (size_t i = 0; i + stride <= snapshot.values.size(); i += stride)
            list.emplace_back(snapshot.values.begin() + long(i), snapshot.values.begin() + long(i + stride));
        if (snapshot.unordered) std::sort(list.begin(), list.end());
        return list;
    };
    std::vector<std::vector<float>> x = entries(a), y = entries(b);
    long differing = long(std::max(x.size(), y.size()) - std::min(x.size(), y.size()));
    for (size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
        bool differs = false;
        for (size_t c = 0; c < stride && !differs; ++c) {
            float u = x[i][c], v = y[i][c];
            if (std::isnan(u) || std::isnan(v)) differs = std::isnan(u) != std::isnan(v);
            else differs = std::fabs(u - v) > float(level) / 255.0f * std::max(1.0f, std::fabs(u));
        }
        differing += differs;
    }
    return differing;
}

}  // namespace oasis
