// Covers src/scene/noise.h: simplex noise range, continuity, determinism, analytic gradients, the fractal sum and hashCell.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include "render/shader_library.h"
#include "scene/noise.h"

namespace oasis {
namespace {

// Skew/unskew factors of the 2D simplex lattice, computed independently of noise.cpp.
const double kF2 = (std::sqrt(3.0) - 1.0) / 2.0;
const double kG2 = (3.0 - std::sqrt(3.0)) / 6.0;
// noise.cpp's documented output scale ("maps the sum to [-1, 1]").
constexpr double kScale = 99.204334582;
// A rigorous Lipschitz constant: each of the three corners contributes t^4 (g.x), t = 0.5 - |x|^2,
// |g| = 1, whose gradient t^4 g - 8 t^3 (g.x) x has magnitude <= u^4 + 8u^3(0.5-u) = 4u^3 - 7u^4
// (u = t), maximal at u = 3/7 where it is 27/343. Three corners, times the scale.
const double kLipschitz = 3.0 * kScale * 27.0 / 343.0;  // about 23.43

glm::vec2 unskew(glm::dvec2 s) { return glm::vec2(s - (s.x + s.y) * kG2); }
glm::dvec2 skew(glm::vec2 p) { return glm::dvec2(p) + (double(p.x) + double(p.y)) * kF2; }

// Which simplex a point is in: the skewed cell and the triangle in it (upper or lower).
struct SimplexId {
    long cx, cy;
    bool lower;
    bool operator!=(const SimplexId& o) const { return cx != o.cx || cy != o.cy || lower != o.lower; }
};
SimplexId simplexOf(glm::vec2 p) {
    glm::dvec2 s = skew(p);
    glm::dvec2 cell = glm::floor(s);
    glm::dvec2 f = s - cell;
    return {long(cell.x), long(cell.y), f.x > f.y};
}

// Five-point ("double step", Richardson-extrapolated) central difference along one axis.
// The point is snapped to a multiple of 1/1024 and h is a power-of-two fraction, so every
// sample coordinate is exact in float and the divisor is exactly 12h.
template <class F>
double fivePointDerivative(F f, glm::vec2 p, int axis, float h) {
    glm::vec2 a = p, b = p, c = p, d = p;
    a[axis] += h;
    b[axis] -= h;
    c[axis] += 2.0f * h;
    d[axis] -= 2.0f * h;
    return (8.0 * (f(a) - f(b)) - (f(c) - f(d))) / (12.0 * double(h));
}

glm::vec2 snap(glm::vec2 p) { return glm::round(p * 1024.0f) / 1024.0f; }

TEST(SimplexNoise, ValueStaysWithinUnitRangeOverLargeSample) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> coord(-300.0f, 300.0f);
    double largest = 0.0;
    for (int i = 0; i < 400000; ++i) {
        glm::vec2 p(coord(rng), coord(rng));
        glm::vec3 n = simplexNoise(p);
        ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)) << p.x << "," << p.y;
        ASSERT_LE(std::fabs(n.x), 1.0 + 1e-6) << "at " << p.x << "," << p.y;
        largest = std::max(largest, double(std::fabs(n.x)));
    }
    // The scale is meant to use the whole range: the sample reaches close to +-1.
    EXPECT_GT(largest, 0.97);
}

TEST(SimplexNoise, AnalyticGradientIsBoundedByLipschitzConstant) {
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> coord(-50.0f, 50.0f);
    for (int i = 0; i < 100000; ++i) {
        glm::vec2 p(coord(rng), coord(rng));
        glm::vec3 n = simplexNoise(p);
        ASSERT_LE(std::hypot(n.y, n.z), kLipschitz) << "at " << p.x << "," << p.y;
    }
}

TEST(SimplexNoise, ContinuousForSmallSteps) {
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> coord(-20.0f, 20.0f), dir(-1.0f, 1.0f);
    int changedSimplex = 0;
    for (int i = 0; i < 100000; ++i) {
        glm::vec2 p(coord(rng), coord(rng));
        glm::vec2 e = 1e-3f * glm::vec2(dir(rng), dir(rng));
        glm::vec2 q = p + e;
        double step = glm::length(glm::dvec2(q) - glm::dvec2(p));
        double change = std::fabs(double(simplexNoise(q).x) - double(simplexNoise(p).x));
        // 2e-5: float rounding of two evaluations near |p| = 20 (x0 carries ~2e-6 error, times |grad| < 8).
        ASSERT_LE(change, kLipschitz * step + 2e-5) << "at " << p.x << "," << p.y;
        if (simplexOf(p) != simplexOf(q)) ++changedSimplex;
    }
    // Random steps of 1e-3 cross a simplex edge now and then; make sure some did.
    EXPECT_GT(changedSimplex, 50);
}

// Steps straddling each kind of simplex edge: skewed x = integer, skewed y = integer, and the
// diagonal inside a cell. A discontinuity (a corner whose kernel does not vanish at the edge, a
// wrong corner offset or cell) shows as a jump far above the Lipschitz bound for a 2e-5 step.
TEST(SimplexNoise, ContinuousAcrossLatticeCellBoundaries) {
    std::mt19937 rng(14);
    std::uniform_int_distribution<int> lattice(-12, 12);
    std::uniform_real_distribution<double> along(0.02, 0.98);
    const double delta = 1e-5;
    int crossings[3] = {0, 0, 0};
    for (int i = 0; i < 30000; ++i) {
        int kind = i % 3;
        int cx = lattice(rng), cy = lattice(rng);
        double t = along(rng);
        glm::dvec2 s, normal;
        if (kind == 0) { s = {cx, cy + t}; normal = {1, 0}; }            // skewed x integer
        else if (kind == 1) { s = {cx + t, cy}; normal = {0, 1}; }       // skewed y integer
        else { s = {cx + t, cy + t}; normal = {1, -1}; }                 // cell diagonal
        glm::vec2 a = unskew(s - delta * normal), b = unskew(s + delta * normal);
        if (!(simplexOf(a) != simplexOf(b))) continue;  // float rounding kept both on one side
        ++crossings[kind];
        double step = glm::length(glm::dvec2(b) - glm::dvec2(a));
        glm::vec3 na = simplexNoise(a), nb = simplexNoise(b);
        // 1e-5: float rounding of two evaluations at |p| < 25.
        ASSERT_LE(std::fabs(double(nb.x) - double(na.x)), kLipschitz * step + 1e-5)
            << "edge kind " << kind << " at skewed " << s.x << "," << s.y;
        // The gradient is continuous as well (the kernel is C^3 at its support's edge).
        ASSERT_LE(std::hypot(double(nb.y - na.y), double(nb.z - na.z)), 1e-2)
            << "gradient jump, edge kind " << kind << " at skewed " << s.x << "," << s.y;
    }
    for (int kind = 0; kind < 3; ++kind) EXPECT_GT(crossings[kind], 9000) << "edge kind " << kind;
}

TEST(SimplexNoise, Deterministic) {
    std::mt19937 rng(15);
    std::uniform_real_distribution<float> coord(-1000.0f, 1000.0f);
    std::vector<glm::vec2> points;
    std::vector<glm::vec3> first;
    for (int i = 0; i < 2000; ++i) {
        points.emplace_back(coord(rng), coord(rng));
        first.push_back(simplexNoise(points.back()));
    }
    for (size_t i = 0; i < points.size(); ++i) {
        glm::vec3 again = simplexNoise(points[i]);
        ASSERT_EQ(first[i].x, again.x);
        ASSERT_EQ(first[i].y, again.y);
        ASSERT_EQ(first[i].z, again.z);
        glm::vec3 f = fractalNoise(points[i], 7), g = fractalNoise(points[i], 7);
        ASSERT_EQ(f.x, g.x);
        ASSERT_EQ(f.y, g.y);
        ASSERT_EQ(f.z, g.z);
    }
}

TEST(SimplexNoise, NotConstant) {
    // Guards the range and continuity tests against a noise that returns zero everywhere.
    std::set<float> values;
    for (int i = 0; i < 100; ++i) values.insert(simplexNoise(glm::vec2(0.37f * float(i), 0.11f * float(i))).x);
    EXPECT_GT(values.size(), 90u);
}

// Five-point differences at h = 1/256 over |p| < 8. Observed error < 3e-4 against gradients up
// to ~7.3 (truncation ~h^4, float rounding ~1e-6 / h); tolerance 1e-3.
TEST(SimplexNoise, AnalyticGradientMatchesFiniteDifferences) {
    std::mt19937 rng(16);
    std::uniform_real_distribution<float> coord(-8.0f, 8.0f);
    auto f = [](glm::vec2 q) { return double(simplexNoise(q).x); };
    const float h = 1.0f / 256.0f;
    double worst = 0.0;
    for (int i = 0; i < 20000; ++i) {
        glm::vec2 p = snap(glm::vec2(coord(rng), coord(rng)));
        glm::vec3 n = simplexNoise(p);
        double dx = fivePointDerivative(f, p, 0, h), dy = fivePointDerivative(f, p, 1, h);
        ASSERT_NEAR(n.y, dx, 1e-3) << "d/dx at " << p.x << "," << p.y;
        ASSERT_NEAR(n.z, dy, 1e-3) << "d/dy at " << p.x << "," << p.y;
        worst = std::max(worst, std::max(std::fabs(n.y - dx), std::fabs(n.z - dy)));
    }
    RecordProperty("worst_abs_error", std::to_string(worst));
}

// Up to 3 octaves the finest layer has frequency 4, so h = 1/256 is still fine: five-point
// differences agree within ~4e-3 (float rounding of the octave coordinates) against gradients
// up to ~20; tolerance 1.5e-2.
TEST(FractalNoise, GradientMatchesFiniteDifferencesForFewOctaves) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> coord(-4.0f, 4.0f);
    const float h = 1.0f / 256.0f;
    for (int octaves = 1; octaves <= 3; ++octaves) {
        auto f = [octaves](glm::vec2 q) { return double(fractalNoise(q, octaves).x); };
        for (int i = 0; i < 10000; ++i) {
            glm::vec2 p = snap(glm::vec2(coord(rng), coord(rng)));
            glm::vec3 n = fractalNoise(p, octaves);
            ASSERT_NEAR(n.y, fivePointDerivative(f, p, 0, h), 1.5e-2)
                << octaves << " octaves, d/dx at " << p.x << "," << p.y;
            ASSERT_NEAR(n.z, fivePointDerivative(f, p, 1, h), 1.5e-2)
                << octaves << " octaves, d/dy at " << p.x << "," << p.y;
        }
    }
}

// With the terrain's 7 octaves the finest layer has frequency 64 (features ~0.02 wide), and its
// coordinates are large enough that float rounding swamps any finite difference small enough to
// resolve it. Instead integrate the analytic gradient along a segment (composite Simpson, 1000
// intervals over length 0.5) and compare with the change in value: observed error < 2e-4
// against changes of order 1; tolerance 1e-3. A wrong Jacobian, rotation or amplitude is off by O(1).
TEST(FractalNoise, GradientIntegratesToValueChangeForAllOctaves) {
    std::mt19937 rng(18);
    std::uniform_real_distribution<double> coord(-4.0, 4.0), angle(0.0, 2.0 * M_PI);
    for (int octaves : {1, 4, 7}) {
        for (int i = 0; i < 100; ++i) {
            glm::dvec2 a(coord(rng), coord(rng));
            double theta = angle(rng);
            glm::dvec2 dir(std::cos(theta), std::sin(theta));
            const double length = 0.5;
            const int intervals = 1000;
            double integral = 0.0;
            for (int k = 0; k <= intervals; ++k) {
                glm::vec3 n = fractalNoise(glm::vec2(a + dir * (length * k / intervals)), octaves);
                double weight = (k == 0 || k == intervals) ? 1.0 : (k % 2 ? 4.0 : 2.0);
                integral += weight * (n.y * dir.x + n.z * dir.y);
            }
            integral *= length / intervals / 3.0;
            double change = double(fractalNoise(glm::vec2(a + dir * length), octaves).x) -
                            double(fractalNoise(glm::vec2(a), octaves).x);
            ASSERT_NEAR(integral, change, 1e-3) << octaves << " octaves from " << a.x << "," << a.y
                                                << " towards " << theta << " rad";
        }
    }
}

// One octave is simplex noise: equal up to the rounding of the float skew, which the fractal sum
// takes in double (the value's gradient is at most ~3 per noise unit, the skew's rounding 1e-5).
TEST(FractalNoise, OneOctaveIsSimplexNoiseAndZeroOctavesIsZero) {
    std::mt19937 rng(19);
    std::uniform_real_distribution<float> coord(-100.0f, 100.0f);
    for (int i = 0; i < 1000; ++i) {
        glm::vec2 p(coord(rng), coord(rng));
        glm::vec3 s = simplexNoise(p), f = fractalNoise(p, 1), z = fractalNoise(p, 0);
        ASSERT_NEAR(s.x, f.x, 1e-4);
        ASSERT_NEAR(s.y, f.y, 1e-3);
        ASSERT_NEAR(s.z, f.z, 1e-3);
        ASSERT_EQ(z, glm::vec3(0.0f));
    }
}

// Around any origin, the fractal sum at origin + local equals the sum taken at the point in
// double: the split into a skewed integer cell and a float fraction loses nothing but rounding,
// also 1e5 noise units out (6.5e7 world units at the default frequency, where a float step is
// 0.008 noise units and plain float evaluation of the finest octave is noise). The limit is the
// cell index, exact in float to 2^24: 1e5 x 64 (octave 6) x 1.37 (skew) = 8.8e6.
TEST(FractalNoise, SumAroundAnOriginEqualsTheExactSum) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> far(-1.0e5, 1.0e5);
    std::uniform_real_distribution<float> near(-2.0f, 2.0f);
    for (int i = 0; i < 300; ++i) {
        glm::dvec2 origin(far(rng), far(rng));
        glm::vec2 local(near(rng), near(rng));
        NoiseOrigins origins = fractalNoiseOrigins(origin, 7);
        glm::vec3 around = fractalNoiseFrom(origins, local, 7);
        glm::vec3 exact = fractalNoise(origin + glm::dvec2(local), 7);
        ASSERT_NEAR(around.x, exact.x, 2e-5) << "at origin (" << origin.x << ", " << origin.y << ")";
        float gradientTolerance = 2e-3f * (1.0f + glm::length(glm::vec2(exact.y, exact.z)));
        ASSERT_NEAR(around.y, exact.y, gradientTolerance);
        ASSERT_NEAR(around.z, exact.z, gradientTolerance);
    }
}

TEST(FractalNoise, SumIsBoundedByGeometricAmplitudes) {
    // Octave k has amplitude 2^-k and each layer is within [-1, 1]: |sum| <= 2 - 2^(1-octaves).
    std::mt19937 rng(20);
    std::uniform_real_distribution<float> coord(-100.0f, 100.0f);
    for (int i = 0; i < 20000; ++i) {
        glm::vec2 p(coord(rng), coord(rng));
        ASSERT_LE(std::fabs(fractalNoise(p, 7).x), 2.0 - std::ldexp(1.0, -6) + 1e-5);
    }
}

// Reference lowbias32-style hash from the documented formula, in 64-bit arithmetic.
uint32_t referenceHash(int x, int y) {
    const uint64_t mask = 0xffffffffull;
    uint64_t h = ((uint64_t(uint32_t(x)) * 0x8da6b343ull) + (uint64_t(uint32_t(y)) * 0xd8163841ull)) & mask;
    h ^= h >> 16; h = (h * 0x7feb352dull) & mask;
    h ^= h >> 15; h = (h * 0x846ca68bull) & mask;
    h ^= h >> 16;
    return uint32_t(h);
}

TEST(HashCell, KnownValues) {
    // Computed with Python's arbitrary-precision integers from the same formula.
    EXPECT_EQ(hashCell({0, 0}), 0u);  // every step of the hash maps 0 to 0
    EXPECT_EQ(hashCell({1, 0}), 0xb0eedb37u);
    EXPECT_EQ(hashCell({0, 1}), 0x7acfe78eu);
    EXPECT_EQ(hashCell({1, 1}), 0x77ee73f9u);
    EXPECT_EQ(hashCell({-1, 0}), 0xf1295adbu);
    EXPECT_EQ(hashCell({0, -1}), 0xcedba691u);
    EXPECT_EQ(hashCell({-1, -1}), 0x3a50a631u);
    EXPECT_EQ(hashCell({123, -456}), 0x1fd922c5u);
}

TEST(HashCell, MatchesReferenceAndNeighboursAreDistinct) {
    for (int cx = -40; cx <= 40; cx += 7) {
        for (int cy = -40; cy <= 40; cy += 9) {
            std::set<uint32_t> neighbourhood;
            for (int dx = -1; dx <= 1; ++dx)
                for (int dy = -1; dy <= 1; ++dy) {
                    uint32_t h = hashCell({cx + dx, cy + dy});
                    ASSERT_EQ(h, referenceHash(cx + dx, cy + dy)) << cx + dx << "," << cy + dy;
                    neighbourhood.insert(h);
                }
            EXPECT_EQ(neighbourhood.size(), 9u) << "around " << cx << "," << cy;
        }
    }
    // Far cells (the camera flies east for hours) hash fine too.
    EXPECT_EQ(hashCell({2000000000, -2000000000}), referenceHash(2000000000, -2000000000));
}

TEST(HashCell, GradientIndicesAreSpreadEvenly) {
    // The low three bits pick one of eight gradients; over 64x64 cells each should get ~1/8.
    int counts[8] = {};
    for (int x = 0; x < 64; ++x)
        for (int y = 0; y < 64; ++y) ++counts[hashCell({x, y}) & 7u];
    for (int k = 0; k < 8; ++k) {
        EXPECT_GT(counts[k], 4096 / 8 - 80) << "gradient " << k;
        EXPECT_LT(counts[k], 4096 / 8 + 80) << "gradient " << k;
    }
}

TEST(HashCell, GlslTwinUsesTheSameConstants) {
    std::string dir = findShaderDirectory();
    ASSERT_FALSE(dir.empty());
    std::ifstream in(dir + "/common/noise.glsl");
    ASSERT_TRUE(in) << dir;
    std::stringstream text;
    text << in.rdbuf();
    for (const char* constant : {"0x8da6b343u", "0xd8163841u", "0x7feb352du", "0x846ca68bu", "99.204334582",
                                 "0.36602540378", "0.21132486540"})
        EXPECT_NE(text.str().find(constant), std::string::npos) << constant;
}

}  // namespace
}  // namespace oasis
