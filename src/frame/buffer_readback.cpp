// Reading the frame's buffers back as the shaders read them (frame/buffer_readback.h).
#include "frame/buffer_readback.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "frame/renderer.h"
#include "gl/objects.h"
#include "render/float_readback.h"
#include "render/light_paths.h"
#include "scene/vegetation.h"

namespace oasis {
namespace {

template <typename T>
std::vector<T> bytesAs(const std::vector<uint8_t>& bytes) {
    std::vector<T> values(bytes.size() / sizeof(T));
    if (!values.empty()) std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
    return values;
}

}  // namespace

std::vector<uint8_t> readBufferBytes(GLuint buffer, size_t offset, size_t bytes) {
    std::vector<uint8_t> out;
    if (!buffer || bytes == 0) return out;
    glBindBuffer(GL_COPY_READ_BUFFER, buffer);
    GLint size = 0;
    glGetBufferParameteriv(GL_COPY_READ_BUFFER, GL_BUFFER_SIZE, &size);
    if (size_t(size) >= offset + bytes) {
        out.resize(bytes);
        if (offset == 0) {
            gl::readBufferData(GL_COPY_READ_BUFFER, GLsizeiptr(bytes), out.data());
        } else {
            // gl::readBufferData reads from a buffer's start: the range is copied into one of its own.
            gl::Buffer range = gl::createBuffer("buffer read-back: a range");
            glBindBuffer(GL_COPY_WRITE_BUFFER, range.name());
            glBufferData(GL_COPY_WRITE_BUFFER, GLsizeiptr(bytes), nullptr, GL_STREAM_READ);
            glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, GLintptr(offset), 0, GLsizeiptr(bytes));
            gl::readBufferData(GL_COPY_WRITE_BUFFER, GLsizeiptr(bytes), out.data());
            glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
        }
    }
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    return out;
}

std::vector<uint32_t> bufferWords(const std::vector<uint8_t>& bytes) { return bytesAs<uint32_t>(bytes); }
std::vector<float> bufferFloats(const std::vector<uint8_t>& bytes) { return bytesAs<float>(bytes); }

// lights_decode.frag draws lightAt(i) into column i (row 0 position and radius, row 1 colour and
// intensity) and lightCount() at (0, 2).
bool readLightsAsShadersSee(Renderer& renderer, std::vector<float>& lights) {
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

std::vector<float> uploadedLights(const FrameSetup& frame) {
    std::vector<float> lights;
    for (const PointLight& light : frame.lights)
        for (const glm::vec4& part : {light.positionRadius, light.colourIntensity})
            lights.insert(lights.end(), {part.x, part.y, part.z, part.w});
    return lights;
}

bool lightReaches(const float* light, const float* p, float radiusScale) {
    float dx = light[0] - p[0], dy = light[1] - p[1], dz = light[2] - p[2];
    float radius = light[3] * radiusScale;
    return dx * dx + dy * dy + dz * dz < radius * radius;
}

size_t plantInstanceFloats() { return sizeof(PlantDrawInstance) / sizeof(float); }

std::vector<float> readPlantInstances(const Renderer& renderer) {
    const VegetationBuffers& plants = renderer.lastFrame().plantInstances;
    size_t count = plants.count(Mirroring::Direct) + plants.count(Mirroring::Mirrored);
    return bufferFloats(readBufferBytes(plants.instanceBuffer(), 0, count * sizeof(PlantDrawInstance)));
}

size_t lightTileOf(int glX, int glY, int width) {
    int across = (width + OASIS_LIGHT_TILE_SIZE - 1) / OASIS_LIGHT_TILE_SIZE;
    return size_t((glY / OASIS_LIGHT_TILE_SIZE) * across + glX / OASIS_LIGHT_TILE_SIZE);
}

float lightSlicePosition(float distance, float nearest, float farthest) {
    return (distance - nearest) / std::max(farthest - nearest, 1e-20f) * float(OASIS_LIGHT_TILE_SLICES);
}

int lightSliceOf(float slicePosition) {
    return int(std::clamp(std::floor(slicePosition), 0.0f, float(OASIS_LIGHT_TILE_SLICES - 1)));
}

std::vector<uint32_t> readLightTiles(GLuint buffer, size_t first, size_t tiles) {
    const size_t tileBytes = kLightTileWords * sizeof(uint32_t);
    return bufferWords(readBufferBytes(buffer, first * tileBytes, tiles * tileBytes));
}

float LightTileWords::nearest() const {
    float value;
    std::memcpy(&value, &tile[0], sizeof(float));
    return value;
}

float LightTileWords::farthest() const {
    float value;
    std::memcpy(&value, &tile[1], sizeof(float));
    return value;
}

uint32_t LightTileWords::count(int slice) const { return tile[2 + size_t(slice) * kLightSliceWords]; }

std::vector<uint32_t> LightTileWords::lights(int slice) const {
    const uint32_t* list = &tile[2 + size_t(slice) * kLightSliceWords + 1];
    return {list, list + std::min<uint32_t>(count(slice), OASIS_LIGHT_TILE_MAX_LIGHTS)};
}

bool LightTileWords::lists(int slice, uint32_t light) const {
    const uint32_t* list = &tile[2 + size_t(slice) * kLightSliceWords + 1];
    const uint32_t* end = list + std::min<uint32_t>(count(slice), OASIS_LIGHT_TILE_MAX_LIGHTS);
    return std::find(list, end, light) != end;
}

}  // namespace oasis
