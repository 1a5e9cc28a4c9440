// Water: the mirror image (the reflection of a surface is that surface as seen directly; of the
// sky, the sky along the mirrored ray), Schlick's Fresnel blend of the composite, the stencil mask
// against an independent CPU depth test of the water plane, reflections changing nothing outside
// the water, and the view from under it (the hard camera poses: water_hard_case_test.cpp).
#include "water_support.h"

#include "debug/debug_views.h"

namespace oasis::gputest {
namespace {
class Water : public GpuTest {};

// ---------------------------------------------------------------------------------------------
// (a) The mirror image. Still, clear water (lakeMirror: ripples 0, absorption 0), deferred, full
// layout. For a water pixel p whose G-buffer holds a reflected surface, its original point is
// P = mirrorY(position(p) + camera); projected with the frame's viewProjection it lands at q.
// Where q is on screen, shows terrain (stencil 1) and sees P itself (the depth at q reconstructs
// to within 2% + 0.5 units of P's distance; else P is hidden there or q is on a silhouette),
// Reflection(p) must match Radiance(q) (bilinear at q's exact position). They are not equal: the
// mirror path lights P as seen from the mirrored camera (specular, the distance of fog and of the
// material's fine detail differ) and q's texels sample the terrain around P. Measured at 640x360:
// relative error (largest channel difference / largest channel) median 0.61%, 95th percentile
// 3.1% (max 63%, at silhouettes); allowed: median 1.5%, 95th percentile 6%. For scale, the same
// comparison one pixel off (q + (1, 1)) gives median 4.5%, 95th percentile 35%. Where the
// reflection shows the sky (SKY flag in the G-buffer), Reflection(p) equals the sky along the
// mirrored ray (CPU port of sky.glsl, sky_model.cpp, clouds included, itself checked against the
// direct sky) within 2e-3 relative (measured 9.7e-4, RGBA16F rounding), and matches the direct
// Radiance where that direction is on screen and shows sky (bilinear: the sky's gradient across a
// pixel; measured max 1.5e-3 with the clouds, 6e-4 before them; allowed 5e-3), where the sky is
// smooth across the four texels (the CPU sky's own bilinear error there under 1e-3: not at a
// cloud's edge, which a bilinear sample blurs; about 40% of those pixels in this pose).
TEST_F(Water, ReflectionIsTheMirroredSceneAsSeenDirectly) {
    constexpr int kW = 640, kH = 360;
    NamedPose pose = poseNamed("lakeMirror");
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kW, kH, layoutNamed("full"));
    FrameReadback r = renderAndRead(renderer, pose.scene, PipelineKind::Deferred);
    const FrameData& f = r.frame.data;
    ASSERT_TRUE(r.frame.reflectionsActive);
    ASSERT_EQ(f.water.z, 0.0f) << "the mirror test needs still water";
    ASSERT_GT(countStencil(r, kStencilWater), kW * kH / 10) << "the lake should fill a good part of the frame";
    checkSkyModel(r, "lakeMirror");

    const double eyeHeight = double(f.cameraPosition.y) - double(f.water.x);
    std::vector<double> surfaceErrors, skyScreenErrors;
    int reflected = 0, offScreen = 0, notTerrain = 0, hidden = 0, bilinearCount = 0, skyNotSmooth = 0;
    auto terrainAt = [&](int x, int y) { return r.stencilAt(x, y) == kStencilTerrain; };
    auto skyAt = [&](int x, int y) { return r.stencilAt(x, y) == kStencilSky; };
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            if (r.stencilAt(x, y) != kStencilWater) continue;
            if (r.flags(x, y) == kSurfaceSky) {
                // The mirrored direction where the camera sees it directly.
                glm::dvec3 ray = pixelRay(f, kW, kH, x, y);
                glm::dvec4 clip = glm::dmat4(f.viewProjection) * glm::dvec4(ray.x, -ray.y, ray.z, 0.0);
                if (clip.w <= 0.0) continue;
                glm::dvec3 q((clip.x / clip.w * 0.5 + 0.5) * kW, (clip.y / clip.w * 0.5 + 0.5) * kH, 0.0);
                if (!onScreen(r, q) || !skyAt(int(q.x), int(q.y))) continue;
                bool bilinear = false;
                glm::dvec3 direct = sampleAt(r, r.radiance, q.x, q.y, skyAt, &bilinear);
                if (!bilinear) continue;
                // Only where the sky is smooth across those texels: bilinear weights on the CPU
                // sky at their centres give the CPU sky at q within 1e-3 (a cloud's edge, a
                // structure smaller than a pixel, is not).
                int x0 = int(std::floor(q.x - 0.5)), y0 = int(std::floor(q.y - 0.5));
                double fx = q.x - 0.5 - x0, fy = q.y - 0.5 - y0;
                auto cpu = [&](int tx, int ty) { return skyRadianceCpu(f, pixelRay(f, kW, kH, tx, ty)); };
                glm::dvec3 smooth = glm::mix(glm::mix(cpu(x0, y0), cpu(x0 + 1, y0), fx),
                                             glm::mix(cpu(x0, y0 + 1), cpu(x0 + 1, y0 + 1), fx), fy);
                if (relativeError(smooth, skyRadianceCpu(f, pixelRay(f, kW, kH, q.x, q.y))) > 1e-3) {
                    ++skyNotSmooth;
                    continue;
                }
                skyScreenErrors.push_back(relativeError(glm::dvec3(r.rgb(r.reflection, x, y)), direct));
                continue;
            }
            ASSERT_EQ(r.flags(x, y), kSurfaceReflected) << "water pixel (" << x << ", " << y << ")";
            ++reflected;
            glm::dvec3 image(texel(r.position, kW, x, y));
            glm::dvec3 original(image.x, -2.0 * eyeHeight - image.y, image.z);  // camera-relative P
            glm::dvec3 q = project(f, kW, kH, original);
            if (!onScreen(r, q)) { ++offScreen; continue; }
            int qx = int(q.x), qy = int(q.y);
            if (!terrainAt(qx, qy)) { ++notTerrain; continue; }
            glm::dvec3 seen = unproject(f, kW, kH, qx, qy, r.depth[r.index(qx, qy)]);
            double distance = glm::length(original);
            if (std::fabs(glm::length(seen) - distance) > 0.02 * distance + 0.5) { ++hidden; continue; }
            bool bilinear = false;
            glm::dvec3 direct = sampleAt(r, r.radiance, q.x, q.y, terrainAt, &bilinear);
            bilinearCount += bilinear ? 1 : 0;
            surfaceErrors.push_back(relativeError(glm::dvec3(r.rgb(r.reflection, x, y)), direct));
        }
    }
    double median = percentile(surfaceErrors, 0.5), p95 = percentile(surfaceErrors, 0.95);
    std::printf("[water] mirror: %d reflected surface px: %zu compared (%d bilinear), %d off screen, %d not terrain "
                "at q, %d hidden/silhouette; relative error median %.4f, p95 %.4f, max %.4f\n",
                reflected, surfaceErrors.size(), bilinearCount, offScreen, notTerrain, hidden, median, p95,
                percentile(surfaceErrors, 1.0));
    EXPECT_GE(surfaceErrors.size(), 2000u) << "too few mirror correspondences to judge";
    EXPECT_LE(median, 0.015) << "reflected surfaces do not look like the same surfaces seen directly";
    EXPECT_LE(p95, 0.06);

    SkyReflectionStats sky = checkSkyReflection(r, [&](int x, int y) { return r.flags(x, y) == kSurfaceSky; });
    std::printf("[water] mirror: %d sky reflection px vs CPU sky: worst relative error %.2e (%d near the sun "
                "skipped); %zu on screen vs direct sky (%d where the sky is not smooth across the texels skipped): "
                "median %.4f, max %.4f\n",
                sky.checked, sky.worst, sky.sensitive, skyScreenErrors.size(), skyNotSmooth,
                percentile(skyScreenErrors, 0.5), percentile(skyScreenErrors, 1.0));
    EXPECT_GT(sky.checked, 1000);
    EXPECT_EQ(sky.wrong, 0) << "sky reflections that are not the sky along the mirrored ray; first " << sky.first;
    EXPECT_GT(skyScreenErrors.size(), 100u);
    EXPECT_LE(percentile(skyScreenErrors, 1.0), 0.005) << "sky reflection differs from the direct sky on screen";
}

// ---------------------------------------------------------------------------------------------
// (b) Fresnel. The frame stopped before WaterCompositePass leaves the under-water colour U in
// Radiance and the reflection R in Reflection; the full frame's Radiance C must be the
// premultiplied blend (ONE, ONE_MINUS_SRC_ALPHA) of shaders/water_composite.frag:
//   C = (F R + glint sun) (1 - fog) + (1 - F (1 - fog)) U,
// F = Schlick(f0, cos) with the still water's normal up (cos = -ray.y through the pixel centre),
// fog = smoothstep(fogStart, viewDistance, distance to the water point), glint = 2 (n.h)^800 (0 at
// night). Pixels where glint is not negligible (> 1e-3 of C) are excluded (none at 10:00 here).
// Tolerance: 1.25 RGBA16F ulps of the expected value (ulp = 2^-10 relative): the blend's float32
// result is stored as half, which llvmpipe truncates (< 1 ulp), and F, fog and the blend run in
// float32 (measured worst: 1.0023 ulps). A wrong F (e.g. f0 or the power off), a missing fog factor
// or a non-premultiplied blend is off by percents. Both pipelines, two still frames: lakeMirror,
// and "flooded" (level 20, fog from 20 to 1000 units, so the far water is fogged up to 0.45).
TEST_F(Water, CompositeIsTheSchlickFresnelBlend) {
    constexpr int kW = 320, kH = 180;
    NamedPose mirror = poseNamed("lakeMirror");
    const std::pair<std::string, SceneSettings> frames[] = {{"lakeMirror", mirror.scene}, {"flooded", floodedScene()}};
    Renderer renderer(*shaders_, mirror.scene);
    renderer.configure(kW, kH, layoutNamed("standard"));
    for (const auto& [name, scene] : frames) {
        for (PipelineKind kind : {PipelineKind::Deferred, PipelineKind::Forward}) {
            SCOPED_TRACE(name + " " + pipelineName(kind));
            FrameReadback before = renderAndRead(renderer, scene, kind, "WaterCompositePass");
            FrameReadback after = renderAndRead(renderer, scene, kind);
            const FrameData& f = after.frame.data;
            ASSERT_TRUE(before.stencil == after.stencil);
            const double f0 = f.waterTint.w, fogStart = f.terrainGridCounts.z, fogEnd = f.terrainGridCounts.w;
            const glm::dvec3 sun(f.sunDirection), sunRadiance(f.sunRadiance);
            // llvmpipe converts the blended float to half by truncation (about half the values are
            // off by more than 1/2 ulp, none by more than 1.003 ulps): allowed 1.25 ulps. A GPU's
            // pow() and fused multiply-adds add their own rounding (H100: worst 2.86 ulps): 4 there.
            const double kUlpTolerance = cpuRasteriser() ? 1.25 : 4.0;
            int checked = 0, glinting = 0, wrong = 0, halfUlps = 0, overOne = 0;
            double worstUlps = 0.0, maxFog = 0.0, minF = 1.0, maxF = 0.0;
            std::string first;
            for (int y = 0; y < kH; ++y) {
                for (int x = 0; x < kW; ++x) {
                    if (after.stencilAt(x, y) != kStencilWater) continue;
                    glm::dvec3 ray = pixelRay(f, kW, kH, x, y), hit;
                    ASSERT_TRUE(rayMeetsWater(f, ray, hit));
                    glm::dvec3 toCamera = -ray;
                    double cosTheta = std::clamp(toCamera.y, 0.0, 1.0);
                    double fresnel = f0 + (1.0 - f0) * std::pow(1.0 - cosTheta, 5.0);
                    double fog = smoothstep(fogStart, fogEnd, glm::length(hit));
                    glm::dvec3 halfway = glm::normalize(sun + toCamera);
                    double glint = sun.y > 0.0 ? 2.0 * std::pow(std::max(halfway.y, 0.0), 800.0) : 0.0;
                    glm::dvec3 u(before.rgb(before.radiance, x, y)), reflection(before.rgb(before.reflection, x, y));
                    glm::dvec3 expected = (fresnel * reflection + glint * sunRadiance) * (1.0 - fog) +
                                          (1.0 - fresnel * (1.0 - fog)) * u;
                    glm::dvec3 got(after.rgb(after.radiance, x, y));
                    if (glint * std::max({sunRadiance.x, sunRadiance.y, sunRadiance.z}) >
                        1e-3 * std::max({expected.x, expected.y, expected.z})) {
                        ++glinting;
                        continue;
                    }
                    ++checked;
                    maxFog = std::max(maxFog, fog);
                    minF = std::min(minF, fresnel);
                    maxF = std::max(maxF, fresnel);
                    for (int c = 0; c < 3; ++c) {
                        // One half-float ulp of the expected value (subnormals below 2^-14: 2^-24).
                        int exponent = int(std::floor(std::log2(std::max(std::fabs(expected[c]), 1e-30))));
                        double ulp = std::ldexp(1.0, std::max(-24, exponent - 10));
                        double ulps = std::fabs(got[c] - expected[c]) / ulp;
                        worstUlps = std::max(worstUlps, ulps);
                        halfUlps += ulps > 0.5 ? 1 : 0;
                        if (ulps > 1.0) ++overOne;
                        if (ulps > kUlpTolerance && wrong++ == 0) {
                            char text[240];
                            std::snprintf(text, sizeof(text),
                                          "(%d, %d from bottom) channel %d: got %.6g, expected %.6g "
                                          "(F %.4f, fog %.4f, U %.6g, R %.6g)",
                                          x, y, c, got[c], expected[c], fresnel, fog, u[c], reflection[c]);
                            first = text;
                        }
                    }
                }
            }
            std::printf("[water] fresnel %s %s: %d water px checked (%d with glint skipped), F %.4f..%.4f, fog up to "
                        "%.3f, worst error %.4f half ulps (%d values > 0.5, %d > 1)\n",
                        name.c_str(), pipelineName(kind), checked, glinting, minF, maxF, maxFog, worstUlps, halfUlps, overOne);
            EXPECT_GT(checked, kW * kH / 20);
            EXPECT_EQ(glinting, 0) << "the sun glints in this frame: the check covers fewer pixels than intended";
            EXPECT_EQ(wrong, 0) << "composite != Schlick blend at " << wrong << " channel values; first " << first;
            if (name == "flooded") {
                EXPECT_GT(maxFog, 0.3) << "no fogged water: the fog term is untested";
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The stencil mask is where the water plane is the nearest surface. The terrain-only depth D_t
// comes from the frame stopped before WaterMaskPass; on the CPU the water's window depth D_w is
// the pixel ray's hit on the plane (inside the quad, +-viewDistance around the camera) projected
// with the frame's viewProjection; expected mask: D_w < D_t (GL_LESS). Frames: default,
// lakeMirror, lakeGrazing, lakeSunset and flooded (level 20, quad +-1000). Mismatches are allowed only
// where |D_w - D_t| <= 32 D24 steps (the water quad's own depth error, see
// gbuffer_properties_test.cpp: up to ~26 steps) or within 0.1% of the quad's outer edge; none are
// expected elsewhere. Also: the full frame's depth is D_t outside the mask and the mask pass's
// depth inside it, bit for bit (WaterCompositePass restores it after the mirrored passes), in both
// pipelines, and the two pipelines' stencils are identical.
TEST_F(Water, StencilMaskIsWhereTheWaterIsNearest) {
    constexpr int kW = 320, kH = 180;
    Renderer renderer(*shaders_, SceneSettings{});
    renderer.configure(kW, kH, layoutNamed("standard"));
    for (const char* name : {"default", "lakeMirror", "lakeGrazing", "lakeSunset", "flooded"}) {
        SCOPED_TRACE(name);
        const SceneSettings scene = sceneNamed(name);
        std::vector<uint8_t> deferredStencil;
        for (PipelineKind kind : {PipelineKind::Deferred, PipelineKind::Forward}) {
            SCOPED_TRACE(pipelineName(kind));
            const std::string afterMask = kind == PipelineKind::Deferred ? "ReflectionClearPass.gbuffer" : "ReflectionClearPass.forward";
            FrameReadback terrain = renderAndRead(renderer, scene, kind, "WaterMaskPass");
            FrameReadback masked = renderAndRead(renderer, scene, kind, afterMask);
            FrameReadback full = renderAndRead(renderer, scene, kind);
            const FrameData& f = full.frame.data;
            ASSERT_TRUE(full.frame.cameraAboveWater);
            EXPECT_EQ(countStencil(terrain, kStencilWater), 0);
            EXPECT_TRUE(masked.stencil == full.stencil) << "stencil changed after the mask pass";
            size_t depthNotRestored = 0, depthNotTerrain = 0;
            for (size_t i = 0; i < full.depth.size(); ++i) {
                depthNotRestored += full.depth[i] != masked.depth[i] ? 1 : 0;
                if (full.stencil[i] != kStencilWater) depthNotTerrain += full.depth[i] != terrain.depth[i] ? 1 : 0;
            }
            EXPECT_EQ(depthNotRestored, 0u) << "the frame's depth is not the mask pass's depth";
            EXPECT_EQ(depthNotTerrain, 0u) << "depth outside the water is not the terrain's";
            if (kind == PipelineKind::Deferred) deferredStencil = full.stencil;
            else {
                EXPECT_TRUE(full.stencil == deferredStencil) << "forward and deferred water masks differ";
                continue;  // the same stencil: the CPU comparison below holds for both
            }

            const double extent = f.terrainGridCounts.w;
            int water = 0, expectedWater = 0, closeCalls = 0, edge = 0, unexplained = 0, beyondQuad = 0;
            double worstCloseSteps = 0.0;
            std::string first;
            for (int y = 0; y < kH; ++y) {
                for (int x = 0; x < kW; ++x) {
                    size_t i = full.index(x, y);
                    bool isWater = full.stencil[i] == kStencilWater;
                    water += isWater ? 1 : 0;
                    glm::dvec3 ray = pixelRay(f, kW, kH, x, y), hit;
                    double waterDepth = 2.0;  // no hit: behind everything
                    bool nearEdge = false;
                    if (rayMeetsWater(f, ray, hit)) {
                        double reach = std::max(std::fabs(hit.x), std::fabs(hit.z));
                        nearEdge = std::fabs(reach - extent) <= 1e-3 * extent;
                        if (reach <= extent) waterDepth = project(f, kW, kH, hit).z;
                        else ++beyondQuad;
                    }
                    bool expected = waterDepth < double(terrain.depth[i]);
                    expectedWater += expected ? 1 : 0;
                    if (expected == isWater) continue;
                    double steps = std::fabs(waterDepth - double(terrain.depth[i])) / kDepthStep;
                    if (steps <= 32.0) {
                        ++closeCalls;
                        worstCloseSteps = std::max(worstCloseSteps, steps);
                    } else if (nearEdge) {
                        ++edge;
                    } else if (unexplained++ == 0) {
                        char text[200];
                        std::snprintf(text, sizeof(text), "(%d, %d from bottom): stencil %d, water depth %.9f, terrain depth %.9f",
                                      x, y, full.stencil[i], waterDepth, double(terrain.depth[i]));
                        first = text;
                    }
                }
            }
            std::printf("[water] mask %s: %d water px (CPU expects %d; %d rays meet the plane beyond the quad); "
                        "mismatches: %d within %.1f D24 steps, %d at the quad's edge, %d unexplained\n",
                        name, water, expectedWater, beyondQuad, closeCalls, worstCloseSteps, edge, unexplained);
            EXPECT_GT(water, kW * kH / 20) << "little water in view";
            EXPECT_EQ(unexplained, 0) << "stencil 2 is not where the water is nearest; first " << first;
            EXPECT_LE(closeCalls, water / 200) << "too many near-tie mismatches";
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Reflections change only the water: Final is bit-identical outside the mask with reflections on
// and off, in both pipelines (and the mask itself is the same); inside it they do change.
TEST_F(Water, ReflectionsChangeNothingOutsideTheWater) {
    constexpr int kW = 320, kH = 180;
    Renderer renderer(*shaders_, SceneSettings{});
    renderer.configure(kW, kH, layoutNamed("standard"));
    for (const std::string name : {"default", "lakeMirror", "lakeSunset"}) {
        SceneSettings on = poseNamed(name).scene, off = on;
        off.water.reflections = false;
        for (PipelineKind kind : {PipelineKind::Deferred, PipelineKind::Forward}) {
            SCOPED_TRACE(name + " " + pipelineName(kind));
            FrameReadback a = renderAndRead(renderer, on, kind);
            FrameReadback b = renderAndRead(renderer, off, kind);
            ASSERT_TRUE(a.stencil == b.stencil) << "the water mask depends on the reflections";
            int outside = 0, inside = 0;
            for (int y = 0; y < kH; ++y)
                for (int x = 0; x < kW; ++x) {
                    if (a.rgb(a.final, x, y) == b.rgb(b.final, x, y)) continue;
                    (a.stencilAt(x, y) == kStencilWater ? inside : outside)++;
                }
            std::printf("[water] reflections on/off %s %s: %d px differ in the water, %d outside\n", name.c_str(),
                        pipelineName(kind), inside, outside);
            EXPECT_EQ(outside, 0) << "reflections changed Final outside the water";
            EXPECT_GT(inside, countStencil(a, kStencilWater) / 10) << "reflections changed almost nothing in the water";
        }
    }
}

// With reflections inactive nothing is reflected: the "reflection" views ("black ... with
// reflections off") and the probe show zero even right after a frame with reflections. The
// Reflection target itself is no longer cleared (issue 30, item 6): it keeps the earlier frame's
// mirror image, which no pass of this frame reads.
TEST_F(Water, ReflectionIsNotShownWhenReflectionsAreInactive) {
    constexpr int kW = 160, kH = 90;
    NamedPose pose = poseNamed("lakeMirror");
    SceneSettings off = pose.scene;
    off.water.reflections = false;
    SceneSettings under = sceneAtHeight(490.0, -3.0, 100.0, 30.0f, -10.0f);  // in the lake, 3 under the surface
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kW, kH, layoutNamed("standard"));
    for (PipelineKind kind : {PipelineKind::Deferred, PipelineKind::Forward}) {
        for (const auto& [label, scene] : {std::make_pair("reflections off", off), std::make_pair("camera under water", under)}) {
            SCOPED_TRACE(std::string(pipelineName(kind)) + ", " + label);
            FrameReadback withReflections = renderAndRead(renderer, pose.scene, kind);
            ASSERT_GT(countStencil(withReflections, kStencilWater), 0);
            FrameReadback r = renderAndRead(renderer, scene, kind);
            ASSERT_FALSE(r.frame.reflectionsActive);
            for (const char* name : {"reflection", "reflection-raw"}) {
                renderer.views().render(name);
                Image view = readDisplay(renderer);
                EXPECT_EQ(rgbStats(view, wholeImage(view)).maxMean(), 0.0) << "the " << name << " view is not black";
            }
            const std::vector<float> values = renderer.views().readValues("reflection");
            EXPECT_EQ(size_t(std::count(values.begin(), values.end(), 0.0f)), values.size())
                << "the reflection view's values are not zero";
        }
    }
}

// A camera a little above the water sees every ray below the horizon meet the water before
// whatever lies under it. Criterion independent of the plane's geometry: a pixel whose terrain
// (frame stopped before WaterMaskPass, reconstructed from depth) lies under the water level must
// be water (stencil 2), because the ray from above the water to that point crosses the surface.
// Heights 0.2, 0.01 and 1e-4 above the water, 5 degrees down over the lake.
TEST_F(Water, SurfaceStaysInViewWithTheCameraJustAboveIt) {
    constexpr int kW = 160, kH = 90;
    Renderer renderer(*shaders_, SceneSettings{});
    renderer.configure(kW, kH, layoutNamed("standard"));
    renderer.setPipeline(PipelineKind::Deferred);
    for (double height : {0.2, 0.01, 1e-4}) {
        SceneSettings scene = sceneAtHeight(490.0, height, 100.0, 30.0f, -5.0f);
        SCOPED_TRACE("camera " + std::to_string(height) + " above the water");
        FrameReadback terrain = renderAndRead(renderer, scene, PipelineKind::Deferred, "WaterMaskPass");
        FrameReadback full = renderAndRead(renderer, scene, PipelineKind::Deferred);
        const FrameData& f = full.frame.data;
        ASSERT_TRUE(full.frame.reflectionsActive);
        int underWater = 0, missing = 0;
        double steepestMissing = 0.0;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                float d = terrain.depth[terrain.index(x, y)];
                if (d >= 1.0f) continue;
                glm::dvec3 point = unproject(f, kW, kH, x, y, d);
                if (point.y + f.cameraPosition.y >= f.water.x - 0.01) continue;  // terrain above (or at) the water
                ++underWater;
                if (full.stencilAt(x, y) == kStencilWater) continue;
                ++missing;
                steepestMissing = std::max(steepestMissing, glm::degrees(std::asin(-pixelRay(f, kW, kH, x, y).y)));
            }
        std::printf("[water] camera %g above the water: %d px see terrain under the water, %d of them without the "
                    "water surface (rays down to %.1f degrees)\n",
                    height, underWater, missing, steepestMissing);
        EXPECT_GT(underWater, kW * kH / 4);
        EXPECT_EQ(missing, 0) << "the water surface is missing where the camera sees the lake bed: the water quad "
                                 "is clipped by the near plane (" << f.depthRange.x << ") where the ray meets the "
                                 "water closer than that";
    }
}


// Under water everything is seen through the water: the mean linear radiance of the view from 3
// units below the surface is shifted towards the water's tint compared with the same view from 3
// units above: its chromaticity (rgb / (r + g + b)) is closer to the tint's, and its red share
// (absorbed fastest) is lower. Nothing writes Reflection under water: a fresh renderer's target is
// what it was before the frame, bit for bit (fresh memory: zeros on llvmpipe, NaNs on zink; it is
// not cleared, ReflectionIsNotShownWhenReflectionsAreInactive).
TEST_F(Water, UnderWaterTheViewIsTintedAndNothingIsReflected) {
    constexpr int kW = 160, kH = 90;
    SceneSettings below = sceneAtHeight(490.0, -3.0, 100.0, 30.0f, -10.0f);
    SceneSettings above = sceneAtHeight(490.0, 3.0, 100.0, 30.0f, -10.0f);
    for (PipelineKind kind : {PipelineKind::Deferred, PipelineKind::Forward}) {
        SCOPED_TRACE(pipelineName(kind));
        Renderer renderer(*shaders_, below);
        renderer.configure(kW, kH, layoutNamed("standard"));
        const std::vector<float> fresh = readTarget(renderer, Target::Reflection);
        FrameReadback under = renderAndRead(renderer, below, kind);
        EXPECT_FALSE(under.frame.reflectionsActive);
        ASSERT_EQ(fresh.size(), under.reflection.size());
        EXPECT_EQ(std::memcmp(fresh.data(), under.reflection.data(), fresh.size() * sizeof(float)), 0)
            << "Reflection written under water";
        FrameReadback over = renderAndRead(renderer, above, kind);
        auto meanChromaticity = [](const FrameReadback& r) {
            glm::dvec3 sum(0.0);
            for (int y = 0; y < r.height; ++y)
                for (int x = 0; x < r.width; ++x) sum += glm::dvec3(r.rgb(r.radiance, x, y));
            return sum / (sum.x + sum.y + sum.z);
        };
        glm::dvec3 tint(under.frame.data.waterTint);
        tint /= tint.x + tint.y + tint.z;
        glm::dvec3 u = meanChromaticity(under), o = meanChromaticity(over);
        std::printf("[water] tint %s: chromaticity below (%.3f, %.3f, %.3f) above (%.3f, %.3f, %.3f) tint (%.3f, %.3f, "
                    "%.3f); distance to tint below %.3f above %.3f\n",
                    pipelineName(kind), u.x, u.y, u.z, o.x, o.y, o.z, tint.x, tint.y, tint.z, glm::length(u - tint),
                    glm::length(o - tint));
        EXPECT_LT(glm::length(u - tint), glm::length(o - tint)) << "the view under water is not shifted to the tint";
        EXPECT_LT(u.x, o.x) << "red is not absorbed under water";
    }
}

}  // namespace
}  // namespace oasis::gputest
