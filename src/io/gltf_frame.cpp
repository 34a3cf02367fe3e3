#include "io/gltf_frame.h"

#include <cmath>

namespace f2 {

std::array<float, 4> quaternionOf(const Mat3& r) {
    const double m00 = r.row[0].x, m01 = r.row[0].y, m02 = r.row[0].z;
    const double m10 = r.row[1].x, m11 = r.row[1].y, m12 = r.row[1].z;
    const double m20 = r.row[2].x, m21 = r.row[2].y, m22 = r.row[2].z;
    const double trace = m00 + m11 + m22;
    double x, y, z, w;
    if (trace > 0) {
        const double s = 2.0 * std::sqrt(1.0 + trace);
        w = s / 4, x = (m21 - m12) / s, y = (m02 - m20) / s, z = (m10 - m01) / s;
    } else if (m00 > m11 && m00 > m22) {
        const double s = 2.0 * std::sqrt(1.0 + m00 - m11 - m22);
        w = (m21 - m12) / s, x = s / 4, y = (m01 + m10) / s, z = (m02 + m20) / s;
    } else if (m11 > m22) {
        const double s = 2.0 * std::sqrt(1.0 + m11 - m00 - m22);
        w = (m02 - m20) / s, x = (m01 + m10) / s, y = s / 4, z = (m12 + m21) / s;
    } else {
        const double s = 2.0 * std::sqrt(1.0 + m22 - m00 - m11);
        w = (m10 - m01) / s, x = (m02 + m20) / s, y = (m12 + m21) / s, z = s / 4;
    }
    // The matrix is a rotation in float: normalise what its rounding left.
    const double n = std::sqrt(x * x + y * y + z * z + w * w);
    return {float(x / n), float(y / n), float(z / n), float(w / n)};
}

GltfPose gltfPoseOf(const Transform& t) {
    // (S·R·S)_ij = s_i s_j R_ij with s = (1, 1, -1): the z row and column change sign.
    Mat3 m = t.linear;
    m.row[0].z = -m.row[0].z;
    m.row[1].z = -m.row[1].z;
    m.row[2].x = -m.row[2].x;
    m.row[2].y = -m.row[2].y;
    const Vec3 p = gltfFromF2(t.translation);
    return {{p.x, p.y, p.z}, quaternionOf(m)};
}

std::array<float, 4> continuousQuaternion(const std::array<float, 4>& q,
                                          const std::array<float, 4>& previous) {
    const float d = q[0] * previous[0] + q[1] * previous[1] + q[2] * previous[2] + q[3] * previous[3];
    if (d >= 0) return q;
    return {-q[0], -q[1], -q[2], -q[3]};
}

}  // namespace f2
