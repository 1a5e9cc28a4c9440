// LightTilingPass: the tiled light method's culling. A compute pass over the G-buffer builds, for
// each OASIS_LIGHT_TILE_SIZE-pixel screen tile, the list of lights whose sphere reaches the tile's
// surfaces (shaders/light_tiles.comp) into a storage buffer this pass owns, left bound for the
// LightingPass of the same half (direct or mirrored) to read. Active only with the tiled method.
#pragma once
#include "passes/pass.h"

namespace oasis {

class LightTilingPass : public Pass {
public:
    explicit LightTilingPass(Mirroring mirroring = Mirroring::Direct) : mirroring_(mirroring) {}
    std::string name() const override {
        return mirroring_ == Mirroring::Mirrored ? "LightTilingPass.mirrored" : "LightTilingPass";
    }
    std::vector<Target> reads() const override {
        return {Target::Albedo, Target::Normal, Target::Position, Target::Info, Target::SceneDepth};
    }
    std::vector<Target> writes() const override { return {}; }  // its own tile-list buffer, no target
    bool reflectionWork() const override { return mirroring_ == Mirroring::Mirrored; }
    bool active(const FrameSetup& frame) const override { return tiledLightsActive(frame, mirroring_); }

    // Whether a half of the deferred frame adds its lights by tiles: the tiled method, lights to add,
    // and the half drawn at all. The LightingPass picks its tiled variant by the same test.
    static bool tiledLightsActive(const FrameSetup& frame, Mirroring mirroring) {
        return frame.lightMethod == LightMethod::Tiled && !frame.lights.empty() && mirroredPassActive(frame, mirroring);
    }
    // Screen tiles across and down a frame, and the bytes of their lists.
    static int tilesAcross(int pixels);
    static size_t listBytes(int width, int height);

protected:
    void execute(PassContext& context) override;

private:
    Mirroring mirroring_;
    gl::Buffer tiles_;
    size_t tilesBytes_ = 0;
};

}  // namespace oasis
