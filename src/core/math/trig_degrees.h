#pragma once
/// Trigonometry of angles in degrees, as the scene language's sin, cos and tan
/// take them (SPEC 9.4). The drives of a grid of objects take sines and
/// cosines every frame (SPEC 10.7), so sin and cos are our own, computed
/// alike one at a time or several side by side (SIMD): the angle is reduced
/// exactly in degrees, and polynomials give the sine and the cosine of the
/// remaining 45 degrees or less, within 0.52 ulp of the true value
/// (docs/scene-language.md; tests/unit/trig_degrees_test.cpp measures it).
#include <cstddef>
#include <optional>

namespace f2 {

/// std::fmod(x, period) for a whole `period`, bit for bit, and faster where
/// x / period is below 1e15.
double wholeRemainder(double x, double period);

/// sin of `degrees`: exactly 0, 1 or -1 at the multiples of 90 (never -0),
/// NaN for what is not finite.
double sinDegrees(double degrees);
/// cos of `degrees`, as sinDegrees.
double cosDegrees(double degrees);

/// How many sines and cosines trigDegreesBatch takes.
inline constexpr std::size_t kTrigBatch = 8;
/// out[i] = sinDegrees(degrees[i]) where cosine[i] is 0, cosDegrees where it
/// is 1, bit for bit, for i < kTrigBatch: side by side when every angle is
/// below 2^50 in size (as a frame's are).
void trigDegreesBatch(const double* degrees, const double* cosine, double* out);

/// tan of `degrees` (libm's of radians past the exact values 0, ±1); none at
/// an odd multiple of 90.
std::optional<double> tanDegrees(double degrees);

}  // namespace f2
