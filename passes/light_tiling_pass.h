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
    std::vector<Access> declaredAccesses(const FrameSetup& frame) const override {
        std::vector<Access> used = gbufferSamples(frame, DepthRead::FromTarget);
        used.push_back({Buffer::LightList, Use::Sample});
        used.push_back({Buffer::LightTiles, Use::Replace});  // its own tile-list buffer
        return used;
    }
    bool reflectionWork() const override { return mirroring_ == Mirroring::Mirrored; }
    // Culled by the frame graph where no LightingPass reads the tiles (another light method).
    bool active(const FrameSetup& frame) const override { return mirroredPassActive(frame, mirroring_); }
    // Screen tiles across and down a frame, and the bytes of their lists.
    static int tilesAcross(int pixels);
    static size_t listBytes(int width, int height);
    // The tile lists of its last dispatch (common/light_tiles.glsl's layout), 0 before one.
    GLuint ownBuffer(Buffer buffer) const override { return buffer == Buffer::LightTiles ? tiles_.name() : 0; }

protected:
    void execute(PassContext& context) override;

private:
    Mirroring mirroring_;
    gl::Buffer tiles_;
    size_t tilesBytes_ = 0;
};

}  // namespace oasis
