// Covers src/scene/sky.h: the day clock (hourAtTime) and the sun and sky state per hour (skyAtHour).
#include <gtest/gtest.h>

#include <cmath>

#include "scene/sky.h"

namespace oasis {
namespace {

TEST(HourAtTime, StartsAtTenAndAdvancesOneDayPerDayLength) {
    EXPECT_EQ(hourAtTime(0.0), 10.0);
    EXPECT_EQ(kStartHour, 10.0);
    EXPECT_NEAR(hourAtTime(kDayLengthSeconds / 24.0), 11.0, 1e-12);      // one simulated hour
    EXPECT_NEAR(hourAtTime(kDayLengthSeconds / 2.0), 22.0, 1e-12);       // half a day later
    EXPECT_NEAR(hourAtTime(kDayLengthSeconds), 10.0, 1e-12);             // a whole day later
    EXPECT_NEAR(hourAtTime(kDayLengthSeconds * 14.0 / 24.0), 0.0, 1e-12);  // 10 + 14 = 24 -> 0
    EXPECT_NEAR(hourAtTime(kDayLengthSeconds * 15.0 / 24.0), 1.0, 1e-12);
    EXPECT_NEAR(hourAtTime(1000.0 * kDayLengthSeconds + 30.0), 11.0, 1e-9);
}

TEST(HourAtTime, NegativeTimesRunTheClockBackwards) {
    EXPECT_NEAR(hourAtTime(-kDayLengthSeconds / 24.0), 9.0, 1e-12);
    EXPECT_NEAR(hourAtTime(-kDayLengthSeconds * 12.0 / 24.0), 22.0, 1e-12);  // 10 - 12 -> 22
    EXPECT_NEAR(hourAtTime(-kDayLengthSeconds * 10.0 / 24.0), 0.0, 1e-12);
    EXPECT_NEAR(hourAtTime(-7.0 * kDayLengthSeconds), 10.0, 1e-9);
}

TEST(HourAtTime, AlwaysInZeroToTwentyFour) {
    for (double t = -5000.0; t <= 5000.0; t += 0.37) {
        double h = hourAtTime(t);
        ASSERT_GE(h, 0.0) << "t = " << t;
        ASSERT_LT(h, 24.0) << "t = " << t;
    }
}

// Just before a time that lands exactly on midnight going backwards (t = -300 s is 0:00), the
// hour is a tiny negative number that fmod keeps and `hour + 24` rounds up to exactly 24.0.
TEST(HourAtTime, StaysBelowTwentyFourJustBeforeMidnightBackwards) {
    const double midnight = -kDayLengthSeconds * 10.0 / 24.0;  // -300 s
    double t = midnight;
    for (int i = 0; i < 4; ++i) {
        t = std::nextafter(t, -1e9);
        double h = hourAtTime(t);
        EXPECT_GE(h, 0.0) << "t = " << t;
        EXPECT_LT(h, 24.0) << "t = " << t << " (one ulp before " << midnight << " s)";
    }
}

TEST(SkyAtHour, SunOnTheHorizonAtSixAndEighteen) {
    SkyState sunrise = skyAtHour(6.0), sunset = skyAtHour(18.0);
    EXPECT_LT(std::fabs(sunrise.sunDirection.y), 1e-6f);
    EXPECT_LT(std::fabs(sunset.sunDirection.y), 1e-6f);
    // Rises in the east (+X), sets in the west (-X).
    EXPECT_NEAR(sunrise.sunDirection.x, 1.0f, 1e-6f);
    EXPECT_NEAR(sunset.sunDirection.x, -1.0f, 1e-6f);
}

TEST(SkyAtHour, NoonSunIsHighAndToTheSouth) {
    SkyState noon = skyAtHour(12.0);
    EXPECT_GT(noon.sunDirection.y, 0.5f);
    EXPECT_GT(noon.sunDirection.z, 0.0f);  // path tilted to the south (+Z)
    EXPECT_NEAR(noon.sunDirection.x, 0.0f, 1e-6f);
    // Noon is the day's highest sun.
    for (double h = 0.0; h < 24.0; h += 0.25) EXPECT_LE(skyAtHour(h).sunDirection.y, noon.sunDirection.y + 1e-6f);
}

TEST(SkyAtHour, SunRadianceZeroAtMidnightAndPositiveAtNoon) {
    SkyState midnight = skyAtHour(0.0), noon = skyAtHour(12.0);
    EXPECT_LT(midnight.sunDirection.y, 0.0f);
    EXPECT_EQ(midnight.sunRadiance, glm::vec3(0.0f));
    EXPECT_GT(noon.sunRadiance.r, 0.0f);
    EXPECT_GT(noon.sunRadiance.g, 0.0f);
    EXPECT_GT(noon.sunRadiance.b, 0.0f);
    // Zero whenever the sun is clearly below the horizon.
    for (double h = 0.0; h < 24.0; h += 0.1) {
        SkyState s = skyAtHour(h);
        if (s.sunDirection.y < -0.01f) {
            ASSERT_EQ(s.sunRadiance, glm::vec3(0.0f)) << "hour " << h;
        }
        ASSERT_GE(s.sunRadiance.r, 0.0f);
        ASSERT_GE(s.sunRadiance.g, 0.0f);
        ASSERT_GE(s.sunRadiance.b, 0.0f);
    }
}

TEST(SkyAtHour, DaySkyBrighterThanNightSky) {
    SkyState midnight = skyAtHour(0.0), noon = skyAtHour(12.0);
    EXPECT_GT(noon.skyZenith.b, midnight.skyZenith.b);
    EXPECT_GT(noon.skyHorizon.g, midnight.skyHorizon.g);
    EXPECT_GT(noon.groundAmbient.r, midnight.groundAmbient.r);
}

TEST(SkyAtHour, SunDirectionIsUnitForManyHours) {
    for (double h = -3.0; h <= 27.0; h += 0.05) {
        SkyState s = skyAtHour(h);
        ASSERT_NEAR(glm::length(s.sunDirection), 1.0f, 1e-6f) << "hour " << h;
        for (int c = 0; c < 3; ++c) {
            ASSERT_TRUE(std::isfinite(s.sunRadiance[c]) && std::isfinite(s.skyZenith[c]) &&
                        std::isfinite(s.skyHorizon[c]) && std::isfinite(s.groundAmbient[c]))
                << "hour " << h;
        }
    }
}

TEST(SkyAtHour, PeriodicOverADay) {
    for (double h = 0.0; h < 24.0; h += 0.5) {
        SkyState a = skyAtHour(h), b = skyAtHour(h + 24.0);
        for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(a.sunDirection[c], b.sunDirection[c], 1e-5f) << "hour " << h;
            ASSERT_NEAR(a.sunRadiance[c], b.sunRadiance[c], 1e-4f) << "hour " << h;
        }
    }
}

}  // namespace
}  // namespace oasis
