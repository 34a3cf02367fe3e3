#include "core/math/trig_degrees.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace f2 {

namespace {

/// wholeRemainder for callers whose period is a constant (1 / period folds).
/// x − period·n with n = ⌊|x| / period⌋ is exact (period·n is a whole number,
/// and by Sterbenz's lemma so is the difference, period·n ≤ |x| < 2·period·n);
/// n from |x| times the rounded 1 / period is off by at most one below 1e15
/// (relative error 2^-52 of a quotient below 2^50), which is put right.
[[gnu::always_inline]] inline double remainderBy(double x, double period) {
    const double a = std::fabs(x);
    if (a < period) return x;  // -0 stays -0, as with fmod
    if (!(a < 1e15)) return std::fmod(x, period);
    const double n = std::floor(a * (1.0 / period));
    double r = a - period * n;
    if (r < 0)
        r = a - period * (n - 1);
    else if (r >= period)
        r = a - period * (n + 1);
    return std::copysign(r, x);
}

// π / 180 as the sum of two doubles, and the Taylor coefficients −1/6 and
// 1/24 likewise: their products are carried to twice a double's precision.
constexpr double kRadiansPerDegree = 0.017453292519943295, kRadiansPerDegreeLow = 2.9486522708701687e-19;
constexpr double kSin3 = -0.16666666666666666, kSin3Low = -9.25185853854297e-18;
constexpr double kCos4 = 0.041666666666666664, kCos4Low = 2.3129646346357427e-18;

/// The rounding error of a·b: a·b = (a*b) + productError(a, b, a*b) exactly.
/// std::fma is exact with or without an FMA unit: every build gets these bits.
[[gnu::always_inline]] inline double productError(double a, double b, double product) {
    return std::fma(a, b, -product);
}

struct SinCos {
    double sin, cos;
};

/// sin and cos of y degrees, |y| ≤ 45 (a little more is fine). In radians
/// the angle is a + lo (lo below an ulp of a). The leading terms of each
/// series, a − a³/6 and 1 − a²/2 + a⁴/24, are summed with their rounding
/// errors, so that only the rest (under 0.3 % of the value for sin, 0.03 %
/// for cos) is rounded in plain doubles: the result is the correctly rounded
/// one except within a few thousandths of an ulp of a midpoint. The tails
/// a⁵·S(a²) and a⁶·C(a²) are fitted at Chebyshev nodes of |a| ≤ π/4 (error
/// below 2^-64 of the value) and summed by Estrin's scheme (short chains).
[[gnu::always_inline]] inline SinCos sinCosReduced(double y) {
    const double a = y * kRadiansPerDegree;
    const double lo = productError(y, kRadiansPerDegree, a) + y * kRadiansPerDegreeLow;
    const double z = a * a;
    const double ze = productError(a, a, z);  // a² = z + ze
    const double z2 = z * z;
    const double z4 = z2 * z2;

    // sin: a + a³·(−1/6) as a sum of two doubles, then the rest.
    const double a3 = a * z;
    const double a3e = productError(a, z, a3) + a * ze;
    const double t3 = a3 * kSin3;
    const double t3e = productError(a3, kSin3, t3) + (a3e * kSin3 + a3 * kSin3Low);
    const double s = a + t3;
    const double se = (a - s) + t3;  // exact: |a| ≥ |t3|
    const double sinTail = a3 * z *
                           ((0.008333333333333333 + z * -0.00019841269841268963) +
                            z2 * (2.755731922232509e-06 + z * -2.5052107236381626e-08) +
                            z4 * (1.6058684400905804e-10 + z * -7.595311845794959e-13));

    // cos: 1 − a²/2 + a⁴/24 likewise.
    const double h = 0.5 * z, he = 0.5 * ze;  // a²/2 = h + he
    const double w = 1 - h;
    const double we = (1 - w) - h;  // exact: 1 ≥ h
    const double z2e = productError(z, z, z2) + 2 * z * ze;
    const double t4 = z2 * kCos4;
    const double t4e = productError(z2, kCos4, t4) + (z2e * kCos4 + z2 * kCos4Low);
    const double c = w + t4;
    const double ce = (w - c) + t4;  // exact: |w| ≥ |t4|
    const double cosTail = z2 * z *
                           ((-0.001388888888888889 + z * 2.4801587301586814e-05) +
                            z2 * (-2.755731922306274e-07 + z * 2.087675634918288e-09) +
                            z4 * (-1.1470545821738428e-11 + z * 4.750660993437302e-14));

    // sin(a + lo) = sin a + lo·cos a, cos(a + lo) = cos a − lo·sin a.
    return {s + ((se + t3e) + (sinTail + lo * c)), c + (((ce + we) + (t4e - he)) + (cosTail - lo * s))};
}

/// sin (cosine 0) or cos (cosine 1) of x degrees, |x| < 2^50, without a
/// branch (the quadrants of a grid's drives differ from object to object,
/// and a batch runs side by side). x − 90·n for the whole n nearest x/90 is
/// exact: 90·n is a whole number below 2^53, and the difference, a multiple
/// of x's ulp (at most 1) and at most 45, fits; so multiples of 90 give
/// exactly 0 and ±1. The rounded 1/90 may pick the n beside the nearest at a
/// tie or far out: y is then a hair past 45, which the polynomials cover.
[[gnu::always_inline]] inline double trigOfSmall(double x, double cosine) {
    const double n = std::nearbyint(x * (1.0 / 90.0));
    const SinCos sc = sinCosReduced(x - 90.0 * n);
    // sin(y + 90k) for k = 0, 1, 2, 3 is sin y, cos y, −sin y, −cos y; and
    // cos(y + 90n) = sin(y + 90(n + 1)).
    // k modulo 4 as m = -2 … 2 (quadrant 3 is -1, 2 is ±2); nearbyint, not
    // floor, as the vectorizer takes it without -fno-trapping-math.
    const double k = n + cosine;
    const double m = k - 4 * std::nearbyint(k * 0.25);
    const double v = std::fabs(m) == 1 ? sc.cos : sc.sin;
    return (m >= 0 && m <= 1 ? v : -v) + 0.0;  // + 0: -0 becomes 0
}

constexpr double kSmall = 0x1p50;

double trigDegrees(double degrees, double cosine) {
    if (std::isnan(degrees) || std::isinf(degrees)) return std::numeric_limits<double>::quiet_NaN();
    return trigOfSmall(std::fabs(degrees) < kSmall ? degrees : remainderBy(degrees, 360.0), cosine);
}

}  // namespace

double wholeRemainder(double x, double period) { return remainderBy(x, period); }

double sinDegrees(double degrees) { return trigDegrees(degrees, 0); }

double cosDegrees(double degrees) { return trigDegrees(degrees, 1); }

void trigDegreesBatch(const double* degrees, const double* cosine, double* out) {
    bool small = true;
    for (std::size_t i = 0; i < kTrigBatch; ++i) small &= std::fabs(degrees[i]) < kSmall;  // NaN: no
    if (!small) {
        for (std::size_t i = 0; i < kTrigBatch; ++i) out[i] = trigDegrees(degrees[i], cosine[i]);
        return;
    }
    for (std::size_t i = 0; i < kTrigBatch; ++i) out[i] = trigOfSmall(degrees[i], cosine[i]);
}

std::optional<double> tanDegrees(double degrees) {
    const double r = remainderBy(degrees, 180.0);
    if (r == 90 || r == -90) return std::nullopt;
    if (r == 0) return 0.0;
    if (r == 45 || r == -135) return 1.0;
    if (r == -45 || r == 135) return -1.0;
    return std::tan(r * (std::numbers::pi / 180.0));
}

}  // namespace f2
