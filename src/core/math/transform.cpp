#include "core/math/transform.h"

#include <algorithm>
#include <cmath>

namespace f2 {

// Exact values at multiples of 90 degrees keep axis-aligned scenes free of 1e-17 noise.
SinCos sinCosDegrees(double deg) {
    if (deg == 0) return {0, 1};  // parts at rest: most angles of a frame
    double r = deg > -360 && deg < 360 ? deg : std::fmod(deg, 360.0);  // fmod is slow and rarely needed
    if (r < 0) r += 360.0;
    if (r == 0) return {0, 1};
    if (r == 90) return {1, 0};
    if (r == 180) return {0, -1};
    if (r == 270) return {-1, 0};
    double a = r * kPi / 180.0;
    return {std::sin(a), std::cos(a)};  // GCC makes this one sincos call
}

Mat3 rotationFromEulerDegrees(double rx, double ry, double rz) {
    if (rx == 0 && ry == 0 && rz == 0) return Mat3{};
    return rotationFromSinCos(sinCosDegrees(rx), sinCosDegrees(ry), sinCosDegrees(rz));
}

Vec3 eulerDegreesFromRotation(const Mat3& rotation) {
    // The bottom row of Rz * Ry * Rx is (-sy, cy sx, cy cx) (rotationFromSinCos), and
    // its first column (cz cy, sz cy, -sy).
    const Vec3* m = rotation.row;
    constexpr double kDegreesPerRadian = 180.0 / kPi;
    const double sy = std::clamp(-double(m[2].x), -1.0, 1.0);
    const double ry = std::asin(sy);
    double rx = 0, rz = 0;
    if (std::fabs(sy) < 1.0 - 1e-6) {
        rx = std::atan2(double(m[2].y), double(m[2].z));
        rz = std::atan2(double(m[1].x), double(m[0].x));
    } else {
        // Gimbal lock: only rx - rz (or rx + rz) is defined; with rz = 0 the
        // middle row is Rx's, (0, cx, -sx).
        rx = std::atan2(-double(m[1].z), double(m[1].y));
    }
    auto degrees = [&](double radians) {
        const double d = radians * kDegreesPerRadian;
        return float(d == -180.0 ? 180.0 : d);
    };
    return {degrees(rx), degrees(ry), degrees(rz)};
}

}  // namespace f2
