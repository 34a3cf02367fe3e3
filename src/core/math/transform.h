#pragma once
/// Rotation matrices (SPEC 1) and rigid transforms `worldFromLocal`.
#include "core/math/vec3.h"

namespace f2 {

/// Row-major 3x3 matrix; columns are the images of the local axes.
struct Mat3 {
    Vec3 row[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

    constexpr Vec3 operator*(Vec3 v) const { return {dot(row[0], v), dot(row[1], v), dot(row[2], v)}; }
    constexpr Vec3 column(int c) const { return {row[0][c], row[1][c], row[2][c]}; }
    constexpr Mat3 transposed() const { return {{column(0), column(1), column(2)}}; }
    constexpr Mat3 operator*(const Mat3& b) const {
        Mat3 r;
        for (int i = 0; i < 3; ++i)
            r.row[i] = {dot(row[i], b.column(0)), dot(row[i], b.column(1)), dot(row[i], b.column(2))};
        return r;
    }
};

inline constexpr double kPi = 3.14159265358979323846;

/// R = Rz(rz) * Ry(ry) * Rx(rx), angles in degrees (SPEC 1, POV-Ray's `rotate`).
/// Computed in double so that 90-degree turns come out exact enough for tests.
Mat3 rotationFromEulerDegrees(double rx, double ry, double rz);

/// Sine and cosine of an angle.
struct SinCos {
    double s = 0, c = 1;
};
/// Of an angle in degrees as rotationFromEulerDegrees takes them: exactly
/// (0, 1) for 0 (either sign), exact at multiples of 90 degrees.
SinCos sinCosDegrees(double degrees);

/// rotationFromEulerDegrees from its angles' sines and cosines. Inline so that
/// a caller that knows an angle is 0 ({0, 1}) has the products by 1 folded
/// away; the arithmetic, and so every bit of the result, stays the same.
inline Mat3 rotationFromSinCos(SinCos x, SinCos y, SinCos z) {
    const auto [sx, cx] = x;
    const auto [sy, cy] = y;
    const auto [sz, cz] = z;
    // Rx: y' = y cx - z sx, z' = y sx + z cx
    // Ry: z' = z cy - x sy, x' = z sy + x cy
    // Rz: x' = x cz - y sz, y' = x sz + y cz
    // Product Rz * Ry * Rx written out in double.
    const double m[3][3] = {
        {cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx},
        {sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx},
        {-sy, cy * sx, cy * cx},
    };
    Mat3 out;
    for (int i = 0; i < 3; ++i) out.row[i] = {float(m[i][0]), float(m[i][1]), float(m[i][2])};
    return out;
}
inline Mat3 rotationFromEulerDegrees(Vec3 r) { return rotationFromEulerDegrees(r.x, r.y, r.z); }

/// The angles (degrees) that rotationFromEulerDegrees turns back into `rotation`:
/// ry in [-90, 90], rx and rz in (-180, 180]. At ry = ±90 (gimbal lock) rz is 0.
/// Used to write a rotation the program computed (a view) as scene text.
Vec3 eulerDegreesFromRotation(const Mat3& rotation);

/// A rotation followed by a translation: world = linear * local + translation.
struct Transform {
    Mat3 linear;
    Vec3 translation;

    constexpr Vec3 applyToPoint(Vec3 p) const { return linear * p + translation; }
    constexpr Vec3 applyToVector(Vec3 v) const { return linear * v; }
    /// `this * inner`: first inner, then this.
    constexpr Transform operator*(const Transform& inner) const {
        return {linear * inner.linear, linear * inner.translation + translation};
    }
    /// `this * (translation by offset)`, without multiplying by an identity matrix.
    constexpr Transform translated(Vec3 offset) const { return {linear, applyToPoint(offset)}; }
    /// Inverse of a rigid transform (the linear part is a rotation).
    constexpr Transform inverseRigid() const {
        Mat3 t = linear.transposed();
        return {t, -(t * translation)};
    }
    static Transform fromPose(Vec3 position, Vec3 rotationDegrees) {
        return {rotationFromEulerDegrees(rotationDegrees), position};
    }
};

}  // namespace f2
