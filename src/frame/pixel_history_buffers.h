// The buffers in the pixel history (frame/pixel_history.h): what the passes of the frame wrote into
// the frame's buffers (passes/pass.h's Buffer) that concerns one pixel, read back as the shaders
// read them (frame/buffer_readback.h): the lights of the light list that reach the pixel's surface
// and the plants' instances (the renderer's uploads before the first pass), the light lists of the
// pixel's tile (LightTilingPass).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

namespace oasis {

class Pass;
class Renderer;

struct LightAtPixel {
    uint32_t index = 0;     // in the list, as the tile lists name it
    glm::vec3 position{0.0f};  // camera-relative, as the shaders read it
    float radius = 0.0f;
    glm::vec3 colour{0.0f};
    float intensity = 0.0f;
};
// LightList: the lights the shaders see, and those whose sphere holds the pixel's surface.
struct LightsAtPixel {
    std::string unreadable;  // why the list could not be read back here, "" when it was
    int count = 0;
    std::optional<glm::vec3> surface;  // camera-relative; none at the sky
    std::vector<LightAtPixel> reaching;
};
// LightTiles: the pixel's tile of a LightTilingPass and its slices' lists.
struct TileAtPixel {
    int tile = 0, column = 0, row = 0;  // index, and place from the bottom-left tile
    float nearest = 0.0f, farthest = 0.0f;  // its surfaces' distances from the camera (nearest > farthest: none)
    std::vector<uint32_t> counts;              // per slice, the true number (past the maximum: every light is used)
    std::vector<std::vector<uint32_t>> lights; // per slice, its list
    int slice = -1;  // the slice the lighting reads for the pixel's surface; -1: no surface known here
};
// PlantInstances: how many billboards the frame draws.
struct PlantsAtPixel {
    size_t direct = 0, mirrored = 0;
};

struct BufferAtPixel {
    std::string buffer;  // the resource's name (resourceName)
    std::variant<LightsAtPixel, TileAtPixel, PlantsAtPixel> what;
};

// The direct scene's surface at GL pixel (glX, glY) of the last frame (whole), camera-relative, as
// its lighting read it (the views' direct fill: under the water at a water pixel); none at the sky.
std::optional<glm::vec3> directSurfaceAt(Renderer& renderer, int glX, int glY);
// The frame's uploads as they concern a pixel whose surface is `surface`.
BufferAtPixel lightsAtPixel(Renderer& renderer, const std::optional<glm::vec3>& surface);
BufferAtPixel plantsAtPixel(const Renderer& renderer);
// The tile lists `pass` (a LightTilingPass of the last frame) holds at GL pixel (glX, glY) of the
// targets it read, `width` pixels wide; the slice of `surface` where given. None where it holds none.
std::optional<BufferAtPixel> tileAtPixel(const Pass& pass, int glX, int glY, int width,
                                         const std::optional<glm::vec3>& surface);

std::string bufferAtPixelText(const BufferAtPixel& buffer);  // lines for people, indented
std::string bufferAtPixelJson(const BufferAtPixel& buffer);  // a JSON object

}  // namespace oasis
