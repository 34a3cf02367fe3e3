// Table 3.1 of the design document: rotations (SPEC 1) and the global <-> local
// point transforms of a placed object. Every expected value is worked out by
// hand in the comment next to it from the SPEC 1 formulas
//   Rx(a): y' = y cos a - z sin a,  z' = y sin a + z cos a
//   Ry(a): z' = z cos a - x sin a,  x' = z sin a + x cos a
//   Rz(a): x' = x cos a - y sin a,  y' = x sin a + y cos a
// with R = Rz * Ry * Rx and world = R * local + position.
#include "core/math/transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <ostream>
#include <random>
#include <string>

#include "test_scenes.h"

namespace f2 {
namespace {

constexpr float kTol = 1e-5f;
const float kSqrtHalf = std::sqrt(0.5f);          // sin 45 = cos 45
const float kSqrt3Half = std::sqrt(3.0f) / 2.0f;  // cos 30 = sin 60

Mat3 identity() { return Mat3{}; }

void expectMatNear(const Mat3& a, const Mat3& b, float tol) {
    for (int i = 0; i < 3; ++i) {
        SCOPED_TRACE(::testing::Message() << "row " << i);
        EXPECT_VEC_NEAR(a.row[i], b.row[i], tol);
    }
}

// --- Single-axis turns: the SPEC 1 sign conventions ---------------------------

TEST(Rotation, PositiveRyTurnsZTowardX) {
    Mat3 r = rotationFromEulerDegrees(0, 90, 0);
    // Ry(90): x' = z*1 + x*0, z' = z*0 - x*1.
    EXPECT_VEC_NEAR(r * Vec3(0, 0, 1), Vec3(1, 0, 0), kTol);   // +z -> +x
    EXPECT_VEC_NEAR(r * Vec3(1, 0, 0), Vec3(0, 0, -1), kTol);  // +x -> -z
    EXPECT_VEC_NEAR(r * Vec3(0, 1, 0), Vec3(0, 1, 0), kTol);   // the axis stays
}

TEST(Rotation, PositiveRxTurnsYTowardZ) {
    Mat3 r = rotationFromEulerDegrees(90, 0, 0);
    // Rx(90): y' = -z, z' = y.
    EXPECT_VEC_NEAR(r * Vec3(0, 1, 0), Vec3(0, 0, 1), kTol);   // +y -> +z
    EXPECT_VEC_NEAR(r * Vec3(0, 0, 1), Vec3(0, -1, 0), kTol);  // +z -> -y
    EXPECT_VEC_NEAR(r * Vec3(1, 0, 0), Vec3(1, 0, 0), kTol);
}

TEST(Rotation, PositiveRzTurnsXTowardY) {
    Mat3 r = rotationFromEulerDegrees(0, 0, 90);
    // Rz(90): x' = -y, y' = x.
    EXPECT_VEC_NEAR(r * Vec3(1, 0, 0), Vec3(0, 1, 0), kTol);   // +x -> +y
    EXPECT_VEC_NEAR(r * Vec3(0, 1, 0), Vec3(-1, 0, 0), kTol);  // +y -> -x
    EXPECT_VEC_NEAR(r * Vec3(0, 0, 1), Vec3(0, 0, 1), kTol);
}

TEST(Rotation, NonRightAngles) {
    // Rz(30) (1,0,0): x' = cos 30 = sqrt(3)/2, y' = sin 30 = 1/2.
    EXPECT_VEC_NEAR(rotationFromEulerDegrees(0, 0, 30) * Vec3(1, 0, 0), Vec3(kSqrt3Half, 0.5f, 0), kTol);
    // Ry(60) (0,0,1): x' = sin 60 = sqrt(3)/2, z' = cos 60 = 1/2.
    EXPECT_VEC_NEAR(rotationFromEulerDegrees(0, 60, 0) * Vec3(0, 0, 1), Vec3(kSqrt3Half, 0, 0.5f), kTol);
    // Rx(-45) (0,1,0): y' = cos(-45) = sqrt(1/2), z' = sin(-45) = -sqrt(1/2).
    EXPECT_VEC_NEAR(rotationFromEulerDegrees(-45, 0, 0) * Vec3(0, 1, 0), Vec3(0, kSqrtHalf, -kSqrtHalf),
                    kTol);
}

TEST(Rotation, RxThenRyOnAPoint) {
    // (1,2,3) under rx=90 first: y' = -z = -3, z' = y = 2 -> (1,-3,2);
    // then ry=90: x' = z = 2, z' = -x = -1 -> (2,-3,-1).
    Mat3 r = rotationFromEulerDegrees(90, 90, 0);
    EXPECT_VEC_NEAR(r * Vec3(1, 2, 3), Vec3(2, -3, -1), kTol);
    // Columns (images of the local axes), by the same two steps:
    // x: (1,0,0) -> (1,0,0) -> (0,0,-1); y: (0,1,0) -> (0,0,1) -> (1,0,0);
    // z: (0,0,1) -> (0,-1,0) -> (0,-1,0).
    EXPECT_VEC_NEAR(r.column(0), Vec3(0, 0, -1), kTol);
    EXPECT_VEC_NEAR(r.column(1), Vec3(1, 0, 0), kTol);
    EXPECT_VEC_NEAR(r.column(2), Vec3(0, -1, 0), kTol);
}

TEST(Rotation, OrderMatters) {
    // The opposite order, ry=90 first: (1,2,3) -> x' = z = 3, z' = -x = -1 -> (3,2,-1);
    // then rx=90: y' = -z = 1, z' = y = 2 -> (3,1,2). Not (2,-3,-1) as above.
    Mat3 ryThenRx = rotationFromEulerDegrees(90, 0, 0) * rotationFromEulerDegrees(0, 90, 0);
    EXPECT_VEC_NEAR(ryThenRx * Vec3(1, 2, 3), Vec3(3, 1, 2), kTol);
    Vec3 euler = rotationFromEulerDegrees(90, 90, 0) * Vec3(1, 2, 3);
    EXPECT_GT(length(euler - Vec3(3, 1, 2)), 1.0f);
}

TEST(Rotation, AllThreeRightAngles) {
    // (1,2,3): rx=90 -> (1,-3,2); ry=90 -> x' = z = 2, z' = -x = -1 -> (2,-3,-1);
    // rz=90 -> x' = -y = 3, y' = x = 2 -> (3,2,-1).
    // That equals ry=90 alone on (1,2,3): x' = 3, z' = -1 -> (3,2,-1).
    Mat3 r = rotationFromEulerDegrees(90, 90, 90);
    EXPECT_VEC_NEAR(r * Vec3(1, 2, 3), Vec3(3, 2, -1), kTol);
    expectMatNear(r, rotationFromEulerDegrees(0, 90, 0), kTol);
}

TEST(Rotation, FullTurnsAreIdentity) {
    expectMatNear(rotationFromEulerDegrees(360, -360, 720), identity(), kTol);
    // -90 and 270 are the same turn.
    expectMatNear(rotationFromEulerDegrees(0, -90, 0), rotationFromEulerDegrees(0, 270, 0), kTol);
    // ry=-90: x' = -z -> (0,0,1) goes to (-1,0,0).
    EXPECT_VEC_NEAR(rotationFromEulerDegrees(0, -90, 0) * Vec3(0, 0, 1), Vec3(-1, 0, 0), kTol);
}

// --- Back from a matrix to angles (the viewer writes computed views as text) ---

TEST(Rotation, EulerAnglesComeBackFromTheMatrix) {
    // Angles inside the ranges eulerDegreesFromRotation returns come back as given.
    const Vec3 cases[] = {{0, 0, 0}, {30, 0, 0}, {0, -45, 0}, {0, 0, 60}, {-20, 35, 170}, {120, -80, -10}};
    for (const Vec3& angles : cases) {
        SCOPED_TRACE(::testing::Message() << "angles " << angles);
        EXPECT_VEC_NEAR(eulerDegreesFromRotation(rotationFromEulerDegrees(angles)), angles, 1e-3f);
    }
    // Outside those ranges other angles give the same rotation: ry = 100 is ry = 80 turned over.
    const Mat3 over = rotationFromEulerDegrees(10, 100, 20);
    const Vec3 back = eulerDegreesFromRotation(over);
    EXPECT_NEAR(back.y, 80.0f, 1e-3f);
    expectMatNear(rotationFromEulerDegrees(back), over, 1e-5f);
    // Gimbal lock (ry = 90): rz is 0 and rx carries the rest of the turn.
    const Mat3 locked = rotationFromEulerDegrees(0, 90, 25);
    const Vec3 lockedBack = eulerDegreesFromRotation(locked);
    EXPECT_EQ(lockedBack.z, 0.0f);
    expectMatNear(rotationFromEulerDegrees(lockedBack), locked, 1e-5f);
}

// --- Table 3.1: local <-> global -------------------------------------------

struct PointCase {
    const char* name;
    Vec3 position, rotation;  ///< the object's Transform (SPEC 1)
    Vec3 local, global;       ///< the same point in both frames, by hand
};

void PrintTo(const PointCase& c, std::ostream* os) {
    *os << c.name << ": pose " << c.position << " rot " << c.rotation << ", local " << c.local
        << " <-> global " << c.global;
}

class LocalGlobal : public ::testing::TestWithParam<PointCase> {};

TEST_P(LocalGlobal, BothDirections) {
    const PointCase& c = GetParam();
    Transform worldFromLocal = Transform::fromPose(c.position, c.rotation);
    Transform localFromWorld = worldFromLocal.inverseRigid();
    EXPECT_VEC_NEAR(worldFromLocal.applyToPoint(c.local), c.global, 1e-4f);
    EXPECT_VEC_NEAR(localFromWorld.applyToPoint(c.global), c.local, 1e-4f);
}

INSTANTIATE_TEST_SUITE_P(
    Table3_1, LocalGlobal,
    ::testing::Values(
        // Identity: both frames agree (the document's placeholder row made real).
        PointCase{"identity", {0, 0, 0}, {0, 0, 0}, {1, 1, 1}, {1, 1, 1}},
        // Pure translation by (10,20,30): global = local + (10,20,30).
        PointCase{"translated", {10, 20, 30}, {0, 0, 0}, {1, 2, 3}, {11, 22, 33}},
        // ... and the world origin is local (-10,-20,-30).
        PointCase{"translated_origin", {10, 20, 30}, {0, 0, 0}, {-10, -20, -30}, {0, 0, 0}},
        // ry=90 at (10,20,30): local (1,0,0) -> R(1,0,0) = (0,0,-1) -> (10,20,29).
        PointCase{"ry90", {10, 20, 30}, {0, 90, 0}, {1, 0, 0}, {10, 20, 29}},
        // ry=90 at (10,20,30), world origin: v = 0 - p = (-10,-20,-30); local = R^T v,
        // rows of R^T = columns of R = (0,0,-1), (0,1,0), (1,0,0) -> (30,-20,-10).
        PointCase{"ry90_origin", {10, 20, 30}, {0, 90, 0}, {30, -20, -10}, {0, 0, 0}},
        // rx=90 then ry=90 at (10,20,30): R(1,2,3) = (2,-3,-1) (see RxThenRyOnAPoint)
        // -> (12,17,29).
        PointCase{"rx90_ry90", {10, 20, 30}, {90, 90, 0}, {1, 2, 3}, {12, 17, 29}},
        // Same pose, world origin: columns (0,0,-1), (1,0,0), (0,-1,0) dotted with
        // (-10,-20,-30) -> (30, -10, 20).
        PointCase{"rx90_ry90_origin", {10, 20, 30}, {90, 90, 0}, {30, -10, 20}, {0, 0, 0}},
        // rz=90 at (5,0,0): local (0,2,0) -> x' = -2, y' = 0 -> (-2,0,0) + (5,0,0) = (3,0,0).
        PointCase{"rz90", {5, 0, 0}, {0, 0, 90}, {0, 2, 0}, {3, 0, 0}},
        // rz=45 at (1,1,0): local (sqrt2,0,0) -> sqrt2*(cos45, sin45, 0) = (1,1,0), + (1,1,0).
        PointCase{"rz45", {1, 1, 0}, {0, 0, 45}, {std::sqrt(2.0f), 0, 0}, {2, 2, 0}},
        // rx=-30 at (0,-105,0): local (0,0,10) -> y' = -10 sin(-30) = 5, z' = 10 cos 30
        // = 5 sqrt3 -> (0, -100, 8.660254).
        PointCase{"rx_minus30", {0, -105, 0}, {-30, 0, 0}, {0, 0, 10}, {0, -100, 10 * kSqrt3Half}}),
    [](const ::testing::TestParamInfo<PointCase>& info) { return std::string(info.param.name); });

TEST(TransformCompose, ParentThenChild) {
    // SPEC 5 frames chain: parent = (rz=90, at (1,0,0)), child = translate (0,2,0).
    // Child origin in world: parent maps (0,2,0) -> Rz90 (0,2,0) = (-2,0,0), + (1,0,0) = (-1,0,0).
    Transform parent = Transform::fromPose({1, 0, 0}, {0, 0, 90});
    Transform child = Transform::fromPose({0, 2, 0}, {0, 0, 0});
    Transform world = parent * child;
    EXPECT_VEC_NEAR(world.applyToPoint({0, 0, 0}), Vec3(-1, 0, 0), kTol);
    // Child local (1,0,0) -> child (1,2,0) -> Rz90: (-2,1,0) -> + (1,0,0) = (-1,1,0).
    EXPECT_VEC_NEAR(world.applyToPoint({1, 0, 0}), Vec3(-1, 1, 0), kTol);
    // Vectors ignore the translation: Rz90 (1,0,0) = (0,1,0).
    EXPECT_VEC_NEAR(world.applyToVector({1, 0, 0}), Vec3(0, 1, 0), kTol);
}

// --- Properties over random angles --------------------------------------------

TEST(RotationProperty, OrthonormalAndProperForRandomAngles) {
    const std::uint32_t seed = test::testSeed(20240531u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> angle(-720.0, 720.0);
    for (int n = 0; n < 2000; ++n) {
        double rx = angle(rng), ry = angle(rng), rz = angle(rng);
        SCOPED_TRACE(::testing::Message() << "angles " << rx << ' ' << ry << ' ' << rz);
        Mat3 r = rotationFromEulerDegrees(rx, ry, rz);
        // R^T R = I: the columns are unit and mutually orthogonal.
        expectMatNear(r.transposed() * r, identity(), 1e-6f);
        // det = +1 (a rotation, not a reflection): col0 x col1 . col2 in any handedness.
        EXPECT_NEAR(dot(cross(r.column(0), r.column(1)), r.column(2)), 1.0f, 1e-6f);
        // The Euler order of SPEC 1: first x, then y, then z, about fixed axes.
        Mat3 composed = rotationFromEulerDegrees(0, 0, rz) * rotationFromEulerDegrees(0, ry, 0) *
                        rotationFromEulerDegrees(rx, 0, 0);
        expectMatNear(r, composed, 1e-6f);
        if (HasFailure()) return;
    }
}

TEST(RotationProperty, SingleAxisMatchesSpecFormula) {
    const std::uint32_t seed = test::testSeed(7u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> angle(-360.0, 360.0);
    for (int n = 0; n < 1000; ++n) {
        double a = angle(rng);
        float c = float(std::cos(a * kPi / 180)), s = float(std::sin(a * kPi / 180));
        SCOPED_TRACE(::testing::Message() << "angle " << a);
        // From SPEC 1 with the other two coordinates zero:
        // Rx (0,1,0) = (0, cos, sin); Ry (0,0,1) = (sin, 0, cos); Rz (1,0,0) = (cos, sin, 0).
        EXPECT_VEC_NEAR(rotationFromEulerDegrees(a, 0, 0) * Vec3(0, 1, 0), Vec3(0, c, s), 1e-6f);
        EXPECT_VEC_NEAR(rotationFromEulerDegrees(0, a, 0) * Vec3(0, 0, 1), Vec3(s, 0, c), 1e-6f);
        EXPECT_VEC_NEAR(rotationFromEulerDegrees(0, 0, a) * Vec3(1, 0, 0), Vec3(c, s, 0), 1e-6f);
        if (HasFailure()) return;
    }
}

TEST(TransformProperty, InverseRigidRoundTrips) {
    const std::uint32_t seed = test::testSeed(99u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> angle(-180.0f, 180.0f), coord(-100.0f, 100.0f);
    for (int n = 0; n < 2000; ++n) {
        Transform t =
            Transform::fromPose({coord(rng), coord(rng), coord(rng)}, {angle(rng), angle(rng), angle(rng)});
        Transform inv = t.inverseRigid();
        Vec3 p{coord(rng), coord(rng), coord(rng)};
        // Coordinates up to ~300 in float: a few ulps of 300 is ~1e-4.
        EXPECT_VEC_NEAR(inv.applyToPoint(t.applyToPoint(p)), p, 2e-4f);  // local -> global -> local
        EXPECT_VEC_NEAR(t.applyToPoint(inv.applyToPoint(p)), p, 2e-4f);  // global -> local -> global
        // Distances are preserved (rigid).
        Vec3 q{coord(rng), coord(rng), coord(rng)};
        EXPECT_NEAR(length(t.applyToPoint(p) - t.applyToPoint(q)), length(p - q), 2e-4f);
        // T * T^-1 is the identity transform.
        Transform id = t * inv;
        expectMatNear(id.linear, identity(), 1e-6f);
        EXPECT_VEC_NEAR(id.translation, Vec3(0, 0, 0), 1e-4f);
        if (HasFailure()) return;
    }
}

}  // namespace
}  // namespace f2
