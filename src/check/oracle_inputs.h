// The shading oracle's inputs (check/shading_oracle.h), read back from the driver after a whole
// frame: the surfaces' texels (deferred: the G-buffer the lighting read; forward: the same surface
// shaders drawn again into float targets, as `probe --shading` does), depth and stencil, the
// frame's Radiance, the shadow maps, the light list and the frame's uniform block; and the surface
// at a pixel decoded on the CPU as common/gbuffer.glsl's readGBuffer() decodes it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "check/oracle_shading.h"
#include "check/oracle_shadow.h"
#include "passes/pass.h"
#include "render/frame_data.h"
#include "render/gbuffer_layout.h"
#include "render/light_data.h"

namespace oasis {

class Renderer;

struct OracleInputs {
    int width = 0, height = 0;
    const GBufferLayout* layout = nullptr;  // the surfaces' layout, which decodes their texels
    bool compact = false;        // positions (and the sky) from depth
    bool depthReversed = false;
    bool forward = false;
    bool lightVolumes = false;   // deferred lights added one blend per light (each a half-float store)
    // Rows bottom-up as GL reads them; RGBA floats, depth floats, stencil bytes.
    std::vector<float> albedo, normal, position, info, depth, radiance;
    std::vector<uint8_t> stencil;
    FrameData frame;
    std::vector<PointLight> lights;
    ShadowMapDepths shadowMaps;  // empty where the frame drew none, or they cannot be read here
    std::string shadowMapsUnreadable;  // why they cannot, where the frame drew them
    std::string shadowMapsHow;         // "read back", or "drawn out (...)" where depth cannot be read
    std::string source;          // where each input came from, for the report
};

OracleInputs readOracleInputs(Renderer& renderer);
// What readOracleInputs and the shading record (probeShading) read of the frame in `layout` as it
// leaves it: the frame's sink for it (FrameViews::setSink's reads), so no target it reads lends
// its memory inside the frame.
std::vector<Resource> oracleReads(const GBufferLayout& layout);

// Whether GL pixel (x, y) shows water (the water mask's stencil mark).
bool oracleWaterAt(const OracleInputs& in, int x, int y);
// The surface at GL pixel (x, y) as readGBuffer() decodes it; false where nothing was drawn (sky).
bool oracleSurfaceAt(const OracleInputs& in, int x, int y, OracleSurface& surface);
// How far, relative to its length, the driver's float arithmetic may have put the position it
// rebuilt from depth at GL pixel (x, y) (the compact layout; 0 where positions are stored): the
// standard convention's eye depth cancels f + n against ndc (f - n) near the far plane.
double oracleRebuiltPositionError(const OracleInputs& in, int x, int y);

}  // namespace oasis
