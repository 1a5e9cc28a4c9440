// The vegetation field: a cache of placed chunks around the camera and the per-frame draw lists.
#include "scene/vegetation.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace oasis {
namespace {

// How far a billboard's top can sway sideways, per unit of its height and of wind strength
// (shaders/vegetation.vert bends the top by at most 0.24 of the height at strength 1).
constexpr double kSwayPerHeight = 0.3;
// The billboard reaches below its base by the atlas cell's margin under the root.
constexpr double kBelowRootPerHeight = 0.05;
// Its cell is square and faces the camera: half its height to either side of the base.
constexpr double kHalfWidthPerHeight = 0.5;

}  // namespace

ChunkBounds plantReach(const PlantInstance& plant) {
    double size = plant.size;
    double side = (kHalfWidthPerHeight + kSwayPerHeight * double(VegetationSettings::kMaxWindStrength)) * size;
    glm::dvec3 base(plant.base);
    return {base - glm::dvec3(side, kBelowRootPerHeight * size, side), base + glm::dvec3(side, size, side)};
}

bool boxMeetsFrustum(const glm::mat4& viewProjection, DepthMapping mapping, glm::vec3 low, glm::vec3 high) {
    for (const glm::vec4& plane : frustumPlanes(viewProjection, mapping)) {
        // The corner furthest along the plane's normal: if even it is outside, the whole box is.
        glm::vec3 corner(plane.x > 0.0f ? high.x : low.x, plane.y > 0.0f ? high.y : low.y,
                         plane.z > 0.0f ? high.z : low.z);
        if (glm::dot(glm::vec3(plane), corner) + plane.w < 0.0f) return false;
    }
    return true;
}

bool chunkRangeAround(const glm::dvec3& camera, double distance, double chunkSize, ChunkRange& range) {
    // In double, checked before any conversion to int: a NaN, a huge coordinate or a huge distance
    // would make the casts undefined and the loops below endless or astronomically long.
    double lowX = std::floor((camera.x - distance) / chunkSize), highX = std::floor((camera.x + distance) / chunkSize);
    double lowZ = std::floor((camera.z - distance) / chunkSize), highZ = std::floor((camera.z + distance) / chunkSize);
    auto indexable = [](double index) { return std::fabs(index) <= kMaxChunkIndex; };  // false for NaN
    if (!(chunkSize > 0.0) || !indexable(lowX) || !indexable(highX) || !indexable(lowZ) || !indexable(highZ) ||
        highX - lowX >= kMaxChunksAcross || highZ - lowZ >= kMaxChunksAcross)
        return false;
    range.first = glm::ivec2(int(lowX), int(lowZ));
    range.last = glm::ivec2(int(highX), int(highZ));
    return true;
}

float drawnFraction(const VegetationSettings& settings, float distance) {
    if (distance > settings.drawDistance) return 0.0f;
    if (distance <= settings.thinningStart) return 1.0f;
    return settings.thinningStart / distance;
}

PlantPlacementSettings VegetationField::defaultPlacement() {
    PlantPlacementSettings placement;
    placement.worldSeed = 0x0A515u;
    placement.chunkSize = 32.0f;
    placement.candidatesPerChunk = 80;  // one candidate per 12.8 square units at density 1
    return placement;
}

VegetationField::VegetationField(PlantPlacementSettings placement)
    : basePlacement_(placement), placement_(placement) {}

bool VegetationField::inRange(glm::ivec2 chunk, const glm::dvec3& camera, float distance) const {
    // The chunk's square against the disc of the draw distance around the camera.
    double size = placement_.chunkSize;
    double nearestX = std::clamp(camera.x, chunk.x * size, (chunk.x + 1) * size);
    double nearestZ = std::clamp(camera.z, chunk.y * size, (chunk.y + 1) * size);
    double dx = nearestX - camera.x, dz = nearestZ - camera.z;
    return dx * dx + dz * dz <= double(distance) * double(distance);
}

VegetationField::ChunkMap::iterator VegetationField::placeChunk(const TerrainShape& shape, glm::ivec2 chunk) {
    Chunk placed;
    placed.plants = placePlantsInChunk(shape, placement_, chunk);
    placed.bounds.low = glm::dvec3(INFINITY);
    placed.bounds.high = glm::dvec3(-INFINITY);
    for (const PlantInstance& plant : placed.plants) {
        ChunkBounds reach = plantReach(plant);
        placed.bounds.low = glm::min(placed.bounds.low, reach.low);
        placed.bounds.high = glm::max(placed.bounds.high, reach.high);
    }
    return chunks_.insert_or_assign({chunk.x, chunk.y}, std::move(placed)).first;
}

void VegetationField::update(const TerrainShape& shape, float waterLevel, const VegetationSettings& settings,
                             uint32_t variantCount, const glm::dvec3& camera) {
    float density = std::clamp(settings.density, 0.0f, VegetationSettings::kMaxDensity);
    bool samePlacement = placedDensity_ == density && placedWaterLevel_ == waterLevel &&
                         placedVariants_ == variantCount && placedShape_.frequency == shape.frequency &&
                         placedShape_.amplitude == shape.amplitude &&
                         placedShape_.baseHeight == shape.baseHeight && placedShape_.octaves == shape.octaves;
    if (!samePlacement) {
        chunks_.clear();
        placement_ = basePlacement_;
        placement_.candidatesPerChunk = int(std::lround(basePlacement_.candidatesPerChunk * density));
        placement_.waterLevel = waterLevel;
        placement_.variantCount = std::max(1u, variantCount);
        placedShape_ = shape;
        placedWaterLevel_ = waterLevel;
        placedDensity_ = density;
        placedVariants_ = variantCount;
    }
    // Forget chunks well out of range (a margin keeps a camera on a chunk edge from thrashing).
    for (auto it = chunks_.begin(); it != chunks_.end();) {
        glm::ivec2 chunk(it->first.first, it->first.second);
        it = inRange(chunk, camera, settings.drawDistance + 2.0f * placement_.chunkSize) ? std::next(it)
                                                                                        : chunks_.erase(it);
    }
    stats_ = VegetationStats{};
    ChunkRange range;
    if (!chunkRangeAround(camera, settings.drawDistance, placement_.chunkSize, range)) return;
    for (int z = range.first.y; z <= range.last.y; ++z)
        for (int x = range.first.x; x <= range.last.x; ++x) {
            glm::ivec2 chunk(x, z);
            if (!inRange(chunk, camera, settings.drawDistance)) continue;
            auto found = chunks_.find({x, z});
            if (found == chunks_.end()) found = placeChunk(shape, chunk);
            stats_.chunksInRange++;
            stats_.plantsPlaced += found->second.plants.size();
        }
}

void VegetationField::buildDrawList(const VegetationSettings& settings, const glm::dvec3& camera,
                                    const glm::mat4& viewProjection, DepthMapping mapping, bool withReflection,
                                    float waterLevel, VegetationDrawList& list, VisibleWaterBound* visibleWater) {
    list.instances.clear();
    list.directCount = list.mirroredCount = 0;
    stats_.chunksVisible = stats_.chunksMirrored = stats_.chunksMirroredOnLand = 0;
    stats_.plantsDrawn = stats_.plantsDrawnMirrored = stats_.plantsMirroredOnLand = 0;
    auto relative = [&](const glm::dvec3& p) { return glm::vec3(p - camera); };
    // Appends the chunk's plants that survive thinning (and, for the mirror images, whose image
    // may land on visible water); returns how many.
    auto appendThinned = [&](const Chunk& chunk, bool mirrored) {
        size_t count = chunk.plants.size(), appended = 0;
        for (size_t i = 0; i < count; ++i) {
            const PlantInstance& plant = chunk.plants[i];
            glm::dvec3 base(plant.base);
            glm::vec3 offset = relative(base);
            float distance = std::sqrt(offset.x * offset.x + offset.z * offset.z);
            // Plants come in random order, so keeping a prefix rank below the fraction thins
            // evenly, and a plant appears or vanishes alone as the camera moves.
            float rank = (float(i) + 0.5f) / float(count);
            if (rank >= drawnFraction(settings, distance)) continue;
            if (mirrored && visibleWater) {
                ChunkBounds reach = plantReach(plant);
                if (!visibleWater->mirrorImageMayShow(reach.low, reach.high)) {
                    stats_.plantsMirroredOnLand++;
                    continue;
                }
            }
            list.instances.push_back({glm::vec4(offset, plant.size), glm::vec4(plant.tint, plant.windPhase),
                                      float(plant.variant)});
            ++appended;
        }
        return appended;
    };
    for (const auto& [key, chunk] : chunks_) {
        if (chunk.plants.empty() || !inRange({key.first, key.second}, camera, settings.drawDistance)) continue;
        if (!boxMeetsFrustum(viewProjection, mapping, relative(chunk.bounds.low), relative(chunk.bounds.high))) continue;
        stats_.chunksVisible++;
        list.directCount += appendThinned(chunk, false);
    }
    if (withReflection) {
        double mirror = 2.0 * double(waterLevel);
        for (const auto& [key, chunk] : chunks_) {
            if (chunk.plants.empty() || !inRange({key.first, key.second}, camera, settings.drawDistance))
                continue;
            glm::dvec3 low(chunk.bounds.low.x, mirror - chunk.bounds.high.y, chunk.bounds.low.z);
            glm::dvec3 high(chunk.bounds.high.x, mirror - chunk.bounds.low.y, chunk.bounds.high.z);
            if (!boxMeetsFrustum(viewProjection, mapping, relative(low), relative(high))) continue;
            if (visibleWater && !visibleWater->mirrorImageMayShow(chunk.bounds.low, chunk.bounds.high)) {
                stats_.chunksMirroredOnLand++;
                continue;
            }
            stats_.chunksMirrored++;
            list.mirroredCount += appendThinned(chunk, true);
        }
    }
    stats_.plantsDrawn = list.directCount;
    stats_.plantsDrawnMirrored = list.mirroredCount;
}

std::vector<PlantInstance> VegetationField::placedPlants() const {
    std::vector<PlantInstance> plants;
    for (const auto& entry : chunks_) plants.insert(plants.end(), entry.second.plants.begin(), entry.second.plants.end());
    return plants;
}

}  // namespace oasis
