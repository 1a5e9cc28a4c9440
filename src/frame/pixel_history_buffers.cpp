// The buffers at one pixel for the pixel history (frame/pixel_history_buffers.h).
#include "frame/pixel_history_buffers.h"

#include <cstdio>

#include "frame/buffer_readback.h"
#include "frame/frame_readback.h"
#include "frame/renderer.h"
#include "io/json_text.h"
#include "passes/pass.h"

namespace oasis {
namespace {

std::vector<double> asDoubles(glm::vec3 v) { return {v.x, v.y, v.z}; }

template <typename T>
std::vector<double> asDoubles(const std::vector<T>& values) {
    return std::vector<double>(values.begin(), values.end());
}

std::string numbersJson(const std::vector<double>& values) { return "[" + numberList(values, ", ", "%.9g", true) + "]"; }

std::string indexListText(const std::vector<uint32_t>& values) {
    return values.empty() ? "none" : numberList(asDoubles(values), ", ", "%.0f");
}

std::string bufferText(const LightsAtPixel& lights) {
    if (!lights.unreadable.empty()) return "      LightList      not read back here: " + lights.unreadable + "\n";
    char line[512];
    std::snprintf(line, sizeof line, "      LightList      %d lights as the shaders read them; ", lights.count);
    std::string text = line;
    if (!lights.surface) return text + "the pixel shows the sky: none reaches a surface\n";
    text += "reaching the pixel's surface (camera-relative " + numberList(asDoubles(*lights.surface), ", ", "%.6g") +
            "): " + std::to_string(lights.reaching.size()) + "\n";
    for (const LightAtPixel& light : lights.reaching) {
        std::snprintf(line, sizeof line, "        light %-4u at %s, radius %.6g, colour %s x %.6g\n", light.index,
                      numberList(asDoubles(light.position), ", ", "%.6g").c_str(), double(light.radius),
                      numberList(asDoubles(light.colour), ", ", "%.4g").c_str(), double(light.intensity));
        text += line;
    }
    return text;
}

std::string bufferText(const TileAtPixel& tile) {
    char line[512];
    std::snprintf(line, sizeof line, "      LightTiles     tile %d (column %d, row %d from the bottom left), ", tile.tile,
                  tile.column, tile.row);
    std::string text = line;
    if (tile.nearest > tile.farthest) {
        text += "no surface in it";
    } else {
        std::snprintf(line, sizeof line, "surfaces %.6g .. %.6g from the camera", double(tile.nearest), double(tile.farthest));
        text += line;
    }
    text += "; lights per slice " + indexListText(tile.counts) + "\n";
    if (tile.slice >= 0) {
        bool all = tile.counts[size_t(tile.slice)] > OASIS_LIGHT_TILE_MAX_LIGHTS;
        text += "        the pixel's surface is in slice " + std::to_string(tile.slice) + ": " +
                (all ? "over the maximum, the lighting adds every light" : "lights " + indexListText(tile.lights[size_t(tile.slice)])) + "\n";
    }
    return text;
}

std::string bufferJson(const TileAtPixel& tile) {
    std::string slices;
    for (size_t s = 0; s < tile.counts.size(); ++s)
        slices += (s ? ", " : "") + std::string("{\"count\": ") + std::to_string(tile.counts[s]) +
                  ", \"lights\": " + numbersJson(asDoubles(tile.lights[s])) + "}";
    return "{\"tile\": " + std::to_string(tile.tile) + ", \"column\": " + std::to_string(tile.column) +
           ", \"row\": " + std::to_string(tile.row) + ", \"nearest\": " + jsonNumber(tile.nearest, 6) +
           ", \"farthest\": " + jsonNumber(tile.farthest, 6) + ", \"slice\": " +
           (tile.slice >= 0 ? std::to_string(tile.slice) : "null") + ", \"lights\": " +
           (tile.slice >= 0 ? numbersJson(asDoubles(tile.lights[size_t(tile.slice)])) : "null") + ", \"slices\": [" + slices + "]}";
}

std::string bufferJson(const LightsAtPixel& lights) {
    if (!lights.unreadable.empty()) return "{\"unreadable\": " + jsonString(lights.unreadable) + "}";
    std::string reaching;
    for (const LightAtPixel& light : lights.reaching)
        reaching += (reaching.empty() ? "" : ", ") + std::string("{\"index\": ") + std::to_string(light.index) +
                    ", \"position\": " + numbersJson(asDoubles(light.position)) + ", \"radius\": " + jsonNumber(light.radius, 6) +
                    ", \"colour\": " + numbersJson(asDoubles(light.colour)) + ", \"intensity\": " + jsonNumber(light.intensity, 6) + "}";
    return "{\"count\": " + std::to_string(lights.count) + ", \"surface\": " +
           (lights.surface ? numbersJson(asDoubles(*lights.surface)) : "null") + ", \"reaching\": [" + reaching + "]}";
}

std::string bufferText(const PlantsAtPixel& plants) {
    return "      PlantInstances " + std::to_string(plants.direct + plants.mirrored) + " billboards (" +
           std::to_string(plants.direct) + " direct, " + std::to_string(plants.mirrored) + " mirrored)\n";
}

std::string bufferJson(const PlantsAtPixel& plants) {
    return "{\"count\": " + std::to_string(plants.direct + plants.mirrored) + ", \"direct\": " +
           std::to_string(plants.direct) + ", \"mirrored\": " + std::to_string(plants.mirrored) + "}";
}

}  // namespace

std::optional<glm::vec3> directSurfaceAt(Renderer& renderer, int glX, int glY) {
    WaterScene asked = renderer.views().waterScene();
    renderer.views().setWaterScene(WaterScene::Direct);
    renderer.views().ensureGBuffer();
    std::vector<float> positions = readSurfacePositions(renderer);
    renderer.views().setWaterScene(asked);
    const float* p = &positions[(size_t(glY) * size_t(renderer.targets().width()) + size_t(glX)) * 4];
    if (p[3] == 0.0f) return std::nullopt;  // the sky: no surface
    return glm::vec3(p[0], p[1], p[2]);
}

BufferAtPixel lightsAtPixel(Renderer& renderer, const std::optional<glm::vec3>& surface) {
    LightsAtPixel at;
    at.surface = surface;
    std::vector<float> lights;
    if (!readLightsAsShadersSee(renderer, lights))
        at.unreadable = "this context cannot draw the list into a float target (no EXT_color_buffer_float)";
    at.count = int(lights.size() / kLightFloats);
    for (size_t i = 0; surface && i + kLightFloats <= lights.size(); i += kLightFloats) {
        const float* light = &lights[i];
        const float p[3] = {surface->x, surface->y, surface->z};
        if (lightReaches(light, p))
            at.reaching.push_back({uint32_t(i / kLightFloats), glm::vec3(light[0], light[1], light[2]), light[3],
                                   glm::vec3(light[4], light[5], light[6]), light[7]});
    }
    return {resourceName(Buffer::LightList), at};
}

BufferAtPixel plantsAtPixel(const Renderer& renderer) {
    const VegetationBuffers& plants = renderer.lastFrame().plantInstances;
    return {resourceName(Buffer::PlantInstances),
            PlantsAtPixel{plants.count(Mirroring::Direct), plants.count(Mirroring::Mirrored)}};
}

std::optional<BufferAtPixel> tileAtPixel(const Pass& pass, int glX, int glY, int width,
                                         const std::optional<glm::vec3>& surface) {
    TileAtPixel tile;
    tile.tile = int(lightTileOf(glX, glY, width));
    tile.column = glX / OASIS_LIGHT_TILE_SIZE;
    tile.row = glY / OASIS_LIGHT_TILE_SIZE;
    std::vector<uint32_t> words = readLightTiles(pass.ownBuffer(Buffer::LightTiles), size_t(tile.tile), 1);
    if (words.empty()) return std::nullopt;
    LightTileWords read{words.data()};
    tile.nearest = read.nearest();
    tile.farthest = read.farthest();
    for (int slice = 0; slice < OASIS_LIGHT_TILE_SLICES; ++slice) {
        tile.counts.push_back(read.count(slice));
        tile.lights.push_back(read.lights(slice));
    }
    if (surface) tile.slice = lightSliceOf(lightSlicePosition(glm::length(*surface), tile.nearest, tile.farthest));
    return BufferAtPixel{resourceName(Buffer::LightTiles), tile};
}

std::string bufferAtPixelText(const BufferAtPixel& buffer) {
    return std::visit([](const auto& what) { return bufferText(what); }, buffer.what);
}

std::string bufferAtPixelJson(const BufferAtPixel& buffer) {
    return std::visit([](const auto& what) { return bufferJson(what); }, buffer.what);
}

}  // namespace oasis
