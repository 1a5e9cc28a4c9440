// The three ways shaders read the point-light list (shaders/common/lights.glsl), how one is chosen
// from the context's capabilities (or forced), and the UBO path's capacity. GL-free: the caller
// passes what the context offers, so the capability report and the unit tests can use it too.
#pragma once
#include <optional>
#include <string>

namespace oasis {

enum class LightsPath { Ssbo, SsboCount, Ubo };

// The most lights a scene may have (the panel's slider, --lights).
inline constexpr int kMaxLights = 4096;

const char* lightsPathName(LightsPath path);          // "ssbo", "ssbo-count", "ubo"
bool parseLightsPath(const std::string& text, LightsPath& out);
const char* lightsPathDefine(LightsPath path);        // "LIGHTS_SSBO", "LIGHTS_SSBO_COUNT", "LIGHTS_UBO"
std::string lightsVariantSuffix(LightsPath path);     // ".lights-ssbo", ... (shader variant names)
std::string lightsPathNames();                        // "ssbo, ssbo-count, ubo"

struct LightsPathChoice {
    LightsPath path = LightsPath::Ubo;
    std::string reason;  // e.g. "ssbo (GL 4.3 / ARB_shader_storage_buffer_object present)"
};
// `forced` (the CLI or the panel) wins unless it asks for an SSBO path the context lacks, which
// falls back to ubo and says so.
// `whyNoSsbo` is the capability report's reason when SSBOs are unavailable (e.g. --force no-ssbo).
LightsPathChoice chooseLightsPath(bool ssboAvailable, std::optional<LightsPath> forced = {},
                                  const std::string& whyNoSsbo = "no GL 4.3 / ARB_shader_storage_buffer_object");

// The UBO path: lights per uniform block (GL_MAX_UNIFORM_BLOCK_SIZE / 32, a multiple of 8 so each
// block's offset is 256-byte aligned) and how many blocks, as a block array, hold kMaxLights —
// no more than the fragment and vertex stages can bind besides the frame and count blocks.
struct UboLightLayout {
    int capacity = 0;  // lights per block
    int blocks = 0;
    int maxLights() const { return capacity * blocks; }  // more than this are dropped (with a warning)
};
UboLightLayout uboLightLayout(int maxUniformBlockSize, int maxUniformBlocksPerStage, int wantedLights = kMaxLights);

}  // namespace oasis
