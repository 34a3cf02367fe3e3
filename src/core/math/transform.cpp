#include "core/math/transform.h"

#include <cmath>

namespace f2 {

namespace {
struct SinCos {
    double s, c;
};
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
    return {std::sin(a), std::cos(a)};
}
}  // namespace

Mat3 rotationFromEulerDegrees(double rx, double ry, double rz) {
    if (rx == 0 && ry == 0 && rz == 0) return Mat3{};
    auto [sx, cx] = sinCosDegrees(rx);
    auto [sy, cy] = sinCosDegrees(ry);
    auto [sz, cz] = sinCosDegrees(rz);
    // Rx: y' = y cx - z sx, z' = y sx + z cx
    // Ry: z' = z cy - x sy, x' = z sy + x cy
    // Rz: x' = x cz - y sz, y' = x sz + y cz
    // Product Rz * Ry * Rx written out in double.
    double m[3][3] = {
        {cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx},
        {sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx},
        {-sy, cy * sx, cy * cx},
    };
    Mat3 out;
    for (int i = 0; i < 3; ++i) out.row[i] = {float(m[i][0]), float(m[i][1]), float(m[i][2])};
    return out;
}

}  // namespace f2
