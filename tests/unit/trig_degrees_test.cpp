// sin and cos of degrees (core/math/trig_degrees.h), our own since drives take
// them every frame: their error against a reference with 11 more bits
// (long double), against libm, the exact values at multiples of 90, and the
// batch of eight side by side against one at a time, bit for bit.
#include "core/math/trig_degrees.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "test_scenes.h"

namespace f2 {
namespace {

/// sin (cosine false) or cos of `degrees` in long double: reduced exactly to
/// y in [-45, 45] as doubles (fmod and y = r − 90·q are exact), then sinl or
/// cosl of y·π/180 (relative error near 2^-63, a thousandth of a double's ulp).
long double reference(double degrees, bool cosine) {
    const double r = std::fmod(degrees, 360.0);
    const double q = std::nearbyint(r / 90);
    const double y = r - 90 * q;
    const int k = (int(q) + (cosine ? 1 : 0)) & 3;
    const long double t = (long double)y * (3.14159265358979323846264338327950288L / 180);
    const long double v = k & 1 ? cosl(t) : sinl(t);
    return k >= 2 ? -v : v;
}

/// The ulp of a double near `v` (the gap above |v|'s binade floor).
long double ulpNear(long double v) {
    const double d = std::fabs(double(v));
    if (d < std::numeric_limits<double>::min()) return std::numeric_limits<double>::denorm_min();
    int exponent = 0;
    std::frexp(d, &exponent);
    return std::ldexp(1.0L, exponent - 53);
}

/// Angles as a scene's drives make them: small and large, near multiples of
/// 90, and every thousandth of a degree over a few turns.
std::vector<double> angles(std::size_t count) {
    std::mt19937_64 random(test::testSeed(11));
    std::uniform_real_distribution<double> unit(-1, 1);
    std::vector<double> out;
    out.reserve(count);
    for (std::size_t i = 0; out.size() < count; ++i) {
        switch (i % 5) {
            case 0:
                out.push_back(360 * unit(random));
                break;
            case 1:
                out.push_back(1e6 * unit(random));
                break;
            case 2:
                out.push_back(std::ldexp(unit(random), int(random() % 60) - 40));  // down to tiny angles
                break;
            case 3:
                out.push_back(std::round(4000 * unit(random)) * 90 +
                              std::ldexp(unit(random), -int(random() % 40)));
                break;
            default:
                out.push_back(double(std::int64_t(i / 5) % 2000000 - 1000000) / 1000);
        }
    }
    return out;
}

TEST(TrigDegrees, WithinHalfAnUlpAndAThousandthAndMostlyCorrectlyRounded) {
    static_assert(std::numeric_limits<long double>::digits >= 64, "the reference needs 11 more bits");
    const std::vector<double> xs = angles(2'000'000);
    for (bool cosine : {false, true}) {
        long double worst = 0;
        double worstAngle = 0;
        std::size_t rounded = 0;
        for (double x : xs) {
            const double got = cosine ? cosDegrees(x) : sinDegrees(x);
            const long double want = reference(x, cosine);
            const long double error = std::fabs((long double)got - want) / ulpNear(want);
            if (error > worst) {
                worst = error;
                worstAngle = x;
            }
            rounded += got == double(want);
        }
        const char* name = cosine ? "cos" : "sin";
        // 0.5 is the correctly rounded value's own error; measured 0.5103.
        EXPECT_LT(worst, 0.52L) << name << " at " << std::hexfloat << worstAngle;
        // Measured: 99.96 % the double nearest to the reference.
        EXPECT_GT(double(rounded) / double(xs.size()), 0.999) << name;
    }
}

TEST(TrigDegrees, WithinTwoUlpsOfLibmOnTheReducedAngle) {
    // libm's sin and cos of the same reduced angle in radians, y·(π/180)
    // rounded once. That rounding moves libm's result by up to an ulp near
    // small angles, so the two may differ by two: measured at most 2, and
    // the same double in 85.6 % of cases.
    const std::vector<double> xs = angles(1'000'000);
    double worst = 0;
    std::size_t same = 0;
    for (double x : xs) {
        const double r = std::fmod(x, 360.0);
        const double q = std::nearbyint(r / 90);
        const double radians = (r - 90 * q) * (3.14159265358979323846 / 180);
        const std::array<double, 4> quadrants = {std::sin(radians), std::cos(radians), -std::sin(radians),
                                                 -std::cos(radians)};
        const double libmSin = quadrants[int(q) & 3];
        const double got = sinDegrees(x);
        worst = std::max(worst, double(std::fabs(got - libmSin) / ulpNear(libmSin)));
        same += got == libmSin;
    }
    EXPECT_LE(worst, 2.0);
    EXPECT_GT(double(same) / double(xs.size()), 0.85);
}

TEST(TrigDegrees, MultiplesOf90AreExactAndNeverNegativeZero) {
    for (double k = -12; k <= 12; ++k) {
        const double x = 90 * k + 360 * 1e9 * (k > 6);  // also far out
        const int quadrant = int(k) & 3;
        const double s = sinDegrees(x), c = cosDegrees(x);
        constexpr std::array<double, 4> kSines = {0.0, 1.0, 0.0, -1.0}, kCosines = {1.0, 0.0, -1.0, 0.0};
        EXPECT_EQ(s, kSines[quadrant]) << x;
        EXPECT_EQ(c, kCosines[quadrant]) << x;
        EXPECT_FALSE(std::signbit(s) && s == 0) << x;
        EXPECT_FALSE(std::signbit(c) && c == 0) << x;
    }
    EXPECT_EQ(std::bit_cast<std::uint64_t>(sinDegrees(-0.0)), 0u);
    // Correctly rounded where the true value is a double (libm's sin of the
    // rounded π/6 gives 0.49999999999999994).
    EXPECT_EQ(sinDegrees(30), 0.5);
    EXPECT_EQ(sinDegrees(150), 0.5);
    EXPECT_EQ(sinDegrees(-210), 0.5);
    EXPECT_EQ(cosDegrees(60), 0.5);
    EXPECT_EQ(cosDegrees(-240), -0.5);
    EXPECT_TRUE(std::isnan(sinDegrees(std::numeric_limits<double>::infinity())));
    EXPECT_TRUE(std::isnan(cosDegrees(std::numeric_limits<double>::quiet_NaN())));
}

TEST(TrigDegrees, ABatchGivesOneAtATimesBits) {
    std::vector<double> xs = angles(400'000);
    // Lanes past 2^50 and not finite take the batch's other path.
    xs[3] = 1e300;
    xs[13] = std::numeric_limits<double>::infinity();
    xs[22] = -std::ldexp(1.0, 50);
    xs[31] = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i + kTrigBatch <= xs.size(); i += kTrigBatch) {
        std::array<double, kTrigBatch> cosine{}, out{};
        for (std::size_t l = 0; l < kTrigBatch; ++l) cosine[l] = double((i / kTrigBatch + l) % 3 == 0);
        trigDegreesBatch(&xs[i], cosine.data(), out.data());
        for (std::size_t l = 0; l < kTrigBatch; ++l) {
            const double want = cosine[l] != 0 ? cosDegrees(xs[i + l]) : sinDegrees(xs[i + l]);
            ASSERT_EQ(std::bit_cast<std::uint64_t>(out[l]), std::bit_cast<std::uint64_t>(want))
                << std::hexfloat << xs[i + l];
        }
    }
}

TEST(TrigDegrees, TheFastRemainderIsFmodBitForBit) {
    // sin, cos and tan reduce their degrees with it.
    std::mt19937_64 random(test::testSeed(7));
    std::vector<double> xs = {0.0,   -0.0,  359.99999999999994, 360.0,  -360.0, 719.9999999999999, 720.0,
                              1e15,  -1e15, 1e15 - 0.5,         9.5e14, 1e300,  -1e-300,           180.0,
                              540.0, -900.0};
    for (int k = 0; k < 200000; ++k) {
        const double scale = std::ldexp(1.0, int(random() % 60) - 10);
        const double x = (double(random() % 2000001) / 1000000.0 - 1.0) * scale;
        xs.push_back(x);
        xs.push_back(std::nextafter(std::round(x / 360) * 360, x));  // just beside a multiple
        xs.push_back(std::nextafter(std::round(x / 180) * 180, -x));
    }
    for (double x : xs) {
        for (double period : {360.0, 180.0}) {
            const double want = std::fmod(x, period), got = wholeRemainder(x, period);
            ASSERT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(want))
                << std::hexfloat << x << " % " << period;
        }
    }
}

}  // namespace
}  // namespace f2
