// Reading back and comparing the buffers of the check's pass-by-pass search (check/check_buffers.h).
#include "check/check_buffers.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "common/shared_constants.glsl"
#include "frame/frame_readback.h"
#include "gl/objects.h"
#include "frame/renderer.h"
#include "passes/light_tiling_pass.h"
#include "render/float_readback.h"
#include "render/light_paths.h"

namespace oasis {
namespace {

constexpr int kSliceStride = OASIS_LIGHT_TILE_MAX_LIGHTS + 1;
constexpr int kTileStride = 2 + OASIS_LIGHT_TILE_SLICES * kSliceStride;
constexpr size_t kLightFloats = 8, kInstanceFloats = sizeof(PlantDrawInstance) / sizeof(float);

// A buffer's first `bytes` as the GL holds them (gl::readBufferData: also on OpenGL ES and in the
// page); empty where the buffer is smaller.
std::vector<uint8_t> readBufferBytes(GLuint buffer, size_t bytes) {
    std::vector<uint8_t> out;
    if (!buffer || bytes == 0) return out;
    glBindBuffer(GL_COPY_READ_BUFFER, buffer);
    GLint size = 0;
    glGetBufferParameteriv(GL_COPY_READ_BUFFER, GL_BUFFER_SIZE, &size);
    if (size_t(size) >= bytes) {
        out.resize(bytes);
        gl::readBufferData(GL_COPY_READ_BUFFER, GLsizeiptr(bytes), out.data());
    }
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    return out;
}

template <typename T>
std::vector<T> asValues(const std::vector<uint8_t>& bytes) {
    std::vector<T> values(bytes.size() / sizeof(T));
    if (!values.empty()) std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
    return values;
}

// The lights as the frame's own light path reads them: lights_decode.frag draws lightAt(i) into
// column i (row 0 position and radius, row 1 colour and intensity) and lightCount() at (0, 2).
// A list longer than the count the shaders see is cut to it, so a count gone wrong shows too.
// False where the context cannot draw into a float target (OpenGL ES without
// EXT_color_buffer_float): that path's lights are then not compared, rather than taken as none.
bool decodeLights(Renderer& renderer, std::vector<float>& lights) {
    const FrameSetup& frame = renderer.lastFrame().setup;
    int uploaded = int(frame.lights.size());
    lights.clear();
    if (uploaded == 0) return true;  // nothing to read: an SSBO path binds no list then
    FloatReadback target;  // made and dropped while the context is current
    target.bindForDrawing(uploaded, 3);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return false;
    }
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glUseProgram(renderer.parts().shaders.program("lights.decode" + lightsVariantSuffix(frame.lightsPath)));
    renderer.parts().geometry.drawFullscreenTriangle();
    std::vector<float> pixels = target.read();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    size_t width = size_t(uploaded);
    int seen = std::clamp(int(pixels[width * 8]), 0, uploaded);
    for (size_t i = 0; i < size_t(seen); ++i) {
        lights.insert(lights.end(), pixels.begin() + long(i * 4), pixels.begin() + long(i * 4 + 4));
        lights.insert(lights.end(), pixels.begin() + long((width + i) * 4), pixels.begin() + long((width + i) * 4 + 4));
    }
    return true;
}

// Whether the light reaches the surface at `p` by more than a part in 10^3 of its radius: the
// compute pass widens the radius by a part in 10^4, so a light this near the edge is never a fault.
bool reaches(const float* light, const float* p) {
    float dx = light[0] - p[0], dy = light[1] - p[1], dz = light[2] - p[2];
    float radius = light[3] * 0.999f;
    return dx * dx + dy * dy + dz * dz < radius * radius;
}

bool inSliceList(const std::vector<uint32_t>& words, size_t sliceBase, uint32_t light) {
    uint32_t count = std::min<uint32_t>(words[sliceBase], OASIS_LIGHT_TILE_MAX_LIGHTS);
    for (uint32_t k = 0; k < count; ++k)
        if (words[sliceBase + 1 + k] == light) return true;
    return false;
}

}  // namespace

std::vector<float> lightTileFaults(const std::vector<uint32_t>& tileWords, const std::vector<float>& positions,
                                   const std::vector<float>& lights, int width, int height) {
    const int across = LightTilingPass::tilesAcross(width);
    std::vector<float> faults(size_t(width) * size_t(height), 0.0f);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            size_t pixel = size_t(y) * size_t(width) + size_t(x);
            const float* p = &positions[pixel * 4];
            if (pixel * 4 + 3 >= positions.size() || p[3] == 0.0f) continue;  // sky: nothing is lit
            size_t base = size_t((y / OASIS_LIGHT_TILE_SIZE) * across + x / OASIS_LIGHT_TILE_SIZE) * kTileStride;
            if (base + kTileStride > tileWords.size()) {
                faults[pixel] = float(lights.size() / kLightFloats);  // no list at all for its tile
                continue;
            }
            float nearest, farthest;
            std::memcpy(&nearest, &tileWords[base], sizeof(float));
            std::memcpy(&farthest, &tileWords[base + 1], sizeof(float));
            // The slice as common/light_tiles.glsl computes it; within 10^-3 of an edge the compute
            // pass lists the light in both slices, and either may be the one the lighting reads.
            float at = (std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - nearest) /
                       std::max(farthest - nearest, 1e-20f) * float(OASIS_LIGHT_TILE_SLICES);
            auto sliceOf = [](float position) {
                // Clamped as a float first: a tile without surfaces has its nearest at 3e38.
                return int(std::clamp(std::floor(position), 0.0f, float(OASIS_LIGHT_TILE_SLICES - 1)));
            };
            int slices[3] = {sliceOf(at), sliceOf(at - 1e-3f), sliceOf(at + 1e-3f)};
            bool overflows = false;
            for (int slice : slices)
                overflows = overflows || tileWords[base + 2 + size_t(slice) * kSliceStride] > OASIS_LIGHT_TILE_MAX_LIGHTS;
            if (overflows) continue;  // the lighting adds every light there
            int missing = 0;
            for (size_t i = 0; i + kLightFloats <= lights.size(); i += kLightFloats) {
                if (!reaches(&lights[i], p)) continue;
                bool found = false;
                for (int slice : slices)
                    found = found || inSliceList(tileWords, base + 2 + size_t(slice) * kSliceStride, uint32_t(i / kLightFloats));
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
        std::vector<uint32_t> words =
            asValues<uint32_t>(readBufferBytes(tiles, LightTilingPass::listBytes(width, height)));
        if (words.empty()) continue;
        std::vector<float> lights;
        for (const PointLight& light : renderer.lastFrame().setup.lights)
            for (const glm::vec4& part : {light.positionRadius, light.colourIntensity})
                lights.insert(lights.end(), {part.x, part.y, part.z, part.w});
        into.pixelChecks.push_back(
            {resourceName(*buffer), lightTileFaults(words, readSurfacePositions(renderer), lights, width, height)});
    }
}

PassSnapshot snapshotFrameInputs(Renderer& renderer) {
    PassSnapshot snapshot{kFrameInputsStep, {}};
    if (std::vector<float> lights; decodeLights(renderer, lights))
        snapshot.buffers.push_back({resourceName(Buffer::LightList), uint32_t(kLightFloats), false, std::move(lights)});
    const VegetationBuffers& plants = renderer.lastFrame().plantInstances;
    size_t count = plants.count(Mirroring::Direct) + plants.count(Mirroring::Mirrored);
    std::vector<float> instances =
        asValues<float>(readBufferBytes(plants.instanceBuffer(), count * sizeof(PlantDrawInstance)));
    // The order of the plants is the placement's, no part of what is drawn.
    snapshot.buffers.push_back({resourceName(Buffer::PlantInstances), uint32_t(kInstanceFloats), true, std::move(instances)});
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
