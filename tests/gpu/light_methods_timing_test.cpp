// docs/lights.md's table of the two deferred light methods (not part of the suite: DISABLED_, run
// by docs/measure_lights.sh): at 1280x720, the default frame at 21:00, standard layout, for 0..4096
// of the scene's lights, the ms each method spends on the lights (volumes: both LightVolumePasses;
// tiled: both LightTilingPasses plus what both LightingPasses take over their 0-light time, measured
// in the same rounds), the whole frame, and each method's marginal cost of a light: the slope of a
// least-squares line through its light ms over the counts, and where the two lines cross.
// Rounds interleave every count and method (OASIS_LIGHT_ROUNDS, default 3); medians, wall time
// around glFinish per pass.
#include <chrono>
#include <cstdlib>

#include "commands/session.h"
#include "gpu_test.h"

namespace oasis::gputest {
namespace {

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

struct Line {
    double slope = 0.0, intercept = 0.0;
};
Line fit(const std::vector<double>& x, const std::vector<double>& y) {
    double n = double(x.size()), sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (size_t i = 0; i < x.size(); ++i) sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
    Line line;
    line.slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    line.intercept = (sy - line.slope * sx) / n;
    return line;
}

TEST_F(GpuTest, DISABLED_LightMethodsTable) {
    const char* roundsText = std::getenv("OASIS_LIGHT_ROUNDS");
    const int rounds = roundsText ? std::max(1, std::atoi(roundsText)) : 3;
    const std::vector<int> counts = {0, 16, 64, 256, 1024, 4096};
    const LightMethod methods[] = {LightMethod::Volumes, LightMethod::Tiled};
    SceneSettings scene;
    scene.hour = 21.0;
    Renderer renderer(*shaders_, scene);
    renderer.configure(1280, 720, layoutNamed("standard"));
    renderer.setPipeline(PipelineKind::Deferred);
    ASSERT_TRUE(renderer.paths().capabilities.compute.available) << "the tiled method needs compute shaders";
    // [method][count] samples: light ms, whole-frame ms, the LightingPasses' ms.
    std::map<std::pair<int, int>, std::vector<double>> lightMs, frameMs, lightingMs, tilingMs;
    for (int round = 0; round < rounds; ++round)
        for (int count : counts)
            for (LightMethod method : methods) {
                scene.lights.count = count;
                scene.lights.method = method;
                if (round == 0) renderer.renderFrame(scene);  // builds the programs, sizes the buffers
                double lights = 0.0, lighting = 0.0, frame = 0.0, tiling = 0.0;
                for (const auto& [name, ms] : medianPassMs(renderer, scene, 1, TimingClock{})) {
                    frame += ms;
                    if (name.rfind("LightVolumePass", 0) == 0 || name.rfind("LightTilingPass", 0) == 0) lights += ms;
                    if (name.rfind("LightingPass", 0) == 0) lighting += ms;
                    if (name.rfind("LightTilingPass", 0) == 0) tiling += ms;
                }
                EXPECT_EQ(renderer.paths().lightMethod.method, method);
                auto key = std::make_pair(int(method), count);
                lightMs[key].push_back(lights);
                lightingMs[key].push_back(lighting);
                frameMs[key].push_back(frame);
                tilingMs[key].push_back(tiling);
            }
    std::printf("| lights | volumes: lights ms | volumes: frame ms | tiled: lights ms (tiling + lighting over its 0-light time) | "
                "tiled: frame ms | tiled / volumes (lights) |\n| --- | --- | --- | --- | --- | --- |\n");
    std::vector<double> x, y[2];
    for (int count : counts) {
        double ms[2], frame[2];
        for (LightMethod method : methods) {
            int m = int(method);
            double floorLighting = median(lightingMs[{m, 0}]);
            ms[m] = median(lightMs[{m, count}]) +
                    (method == LightMethod::Tiled ? median(lightingMs[{m, count}]) - floorLighting : 0.0);
            frame[m] = median(frameMs[{m, count}]);
            y[m].push_back(ms[m]);
        }
        x.push_back(double(count));
        std::printf("| %d | %.1f | %.1f | %.1f | %.1f | %s |\n", count, ms[0], frame[0], ms[1], frame[1],
                    count ? (std::to_string(ms[1] / ms[0]).substr(0, 4)).c_str() : "-");
    }
    Line volumes = fit(x, y[0]), tiled = fit(x, y[1]);
    std::printf("\nmarginal cost of a light (least-squares slope over %zu counts): volumes %.4f ms, tiled %.4f ms "
                "(%.1fx less); at 4096 lights: volumes %.4f ms, tiled %.4f ms per light\n",
                counts.size(), volumes.slope, tiled.slope, volumes.slope / tiled.slope, y[0].back() / 4096.0,
                y[1].back() / 4096.0);
    double cross = (tiled.intercept - volumes.intercept) / (volumes.slope - tiled.slope);
    std::printf("lines: volumes %.2f + %.4f n ms, tiled %.2f + %.4f n ms; they cross at n = %.0f\n", volumes.intercept,
                volumes.slope, tiled.intercept, tiled.slope, cross);
    int t = int(LightMethod::Tiled);
    std::printf("tiled at %d lights: LightTilingPasses %.1f ms, LightingPasses %.1f ms (%.1f with no lights)\n",
                counts.back(), median(tilingMs[{t, counts.back()}]), median(lightingMs[{t, counts.back()}]),
                median(lightingMs[{t, 0}]));
    std::printf("renderer: %s; %d rounds, medians\n", queryContextInfo().renderer.c_str(), rounds);
}

}  // namespace
}  // namespace oasis::gputest
