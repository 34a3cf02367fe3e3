// Tables 3.2-3.4 of the design document: ray against sphere, cylinder and box
// (SPEC 4), with every expected point and normal worked out by hand in the
// comment beside it, then seeded property tests in the style of pbrt's shape
// tests. Sizes follow SceneObject: sphere (r,0,0), cylinder (r,h,0) with the
// axis on local y and caps at y = +-h/2, box (sx,sy,sz) full sides.
#include "core/geometry/intersect.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <random>

#include "test_scenes.h"

namespace f2 {
namespace {

const float kSqrtHalf = std::sqrt(0.5f);
const float kSqrt2 = std::sqrt(2.0f);

Primitive sphere(float r, Vec3 pos = {}, Vec3 rot = {}) {
    return makePrimitive(ShapeKind::Sphere, {r, 0, 0}, Transform::fromPose(pos, rot));
}
Primitive cylinder(float r, float h, Vec3 pos = {}, Vec3 rot = {}) {
    return makePrimitive(ShapeKind::Cylinder, {r, h, 0}, Transform::fromPose(pos, rot));
}
Primitive box(Vec3 size, Vec3 pos = {}, Vec3 rot = {}) {
    return makePrimitive(ShapeKind::Box, size, Transform::fromPose(pos, rot));
}

struct Hit {
    bool ok = false;
    float t = 0;
    Vec3 point, normal;
};

/// One intersectPrimitive call; the direction is normalised here (rays are unit).
Hit trace(const Primitive& prim, Vec3 origin, Vec3 direction, float tMin = 0, float tMax = kInfinity) {
    Ray ray{origin, normalize(direction)};
    Hit h;
    Face face;
    h.ok = intersectPrimitive(prim, ray, tMin, tMax, h.t, face);
    if (h.ok) {
        h.point = ray.origin + ray.direction * h.t;
        h.normal = primitiveNormal(prim, h.point, face);
    }
    return h;
}

#define EXPECT_HIT(h, tExpected, pointExpected, normalExpected) \
    do {                                                        \
        const Hit h_ = (h);                                     \
        ASSERT_TRUE(h_.ok) << "expected a hit";                 \
        EXPECT_NEAR(h_.t, (tExpected), 1e-4f);                  \
        EXPECT_VEC_NEAR(h_.point, (pointExpected), 1e-4f);      \
        EXPECT_VEC_NEAR(h_.normal, (normalExpected), 1e-5f);    \
    } while (0)

bool near(Vec3 a, Vec3 b, float tol) { return length(a - b) <= tol; }

// ============================ Table 3.2: sphere ============================

TEST(SphereIntersect, HeadOnFromOutside) {
    // r=10 at the origin, ray from (0,0,-20) along +z: |(0,0,-20+t)| = 10 -> t = 10,
    // point (0,0,-10), outward normal (0,0,-1).
    EXPECT_HIT(trace(sphere(10), {0, 0, -20}, {0, 0, 1}), 10.0f, Vec3(0, 0, -10), Vec3(0, 0, -1));
}

TEST(SphereIntersect, OffCentreFromOutside) {
    // r=5, ray x=3 along +z from z=-10: 9 + z^2 = 25 -> z = -4, t = 6,
    // normal = (3,0,-4)/5.
    EXPECT_HIT(trace(sphere(5), {3, 0, -10}, {0, 0, 1}), 6.0f, Vec3(3, 0, -4), Vec3(0.6f, 0, -0.8f));
}

TEST(SphereIntersect, Miss) {
    // The line y=11 passes 11 > 10 from the centre.
    EXPECT_FALSE(trace(sphere(10), {0, 11, -20}, {0, 0, 1}).ok);
    // Pointing away from the sphere.
    EXPECT_FALSE(trace(sphere(10), {0, 0, -20}, {0, 0, -1}).ok);
}

TEST(SphereIntersect, NearlyTangent) {
    // Line y=9.99: z^2 = 100 - 99.8001 = 0.1999, z = -0.4471018, t = 20 - 0.4471018.
    float z = std::sqrt(100.0f - 9.99f * 9.99f);
    Hit h = trace(sphere(10), {0, 9.99f, -20}, {0, 0, 1});
    EXPECT_HIT(h, 20.0f - z, Vec3(0, 9.99f, -z), Vec3(0, 0.999f, -z / 10));
    // Line y=10.01 clears it.
    EXPECT_FALSE(trace(sphere(10), {0, 10.01f, -20}, {0, 0, 1}).ok);
    // Exactly tangent at (0,10,0): the solid is closed, the touching point counts.
    EXPECT_HIT(trace(sphere(10), {0, 10, -20}, {0, 0, 1}), 20.0f, Vec3(0, 10, 0), Vec3(0, 1, 0));
}

TEST(SphereIntersect, OriginInsideReturnsExit) {
    // From the centre along +x: exit at (10,0,0), t = 10, normal still outward.
    EXPECT_HIT(trace(sphere(10), {0, 0, 0}, {1, 0, 0}), 10.0f, Vec3(10, 0, 0), Vec3(1, 0, 0));
    // From (6,0,0) along +y: 36 + y^2 = 100 -> y = 8, normal (6,8,0)/10.
    EXPECT_HIT(trace(sphere(10), {6, 0, 0}, {0, 1, 0}), 8.0f, Vec3(6, 8, 0), Vec3(0.6f, 0.8f, 0));
}

TEST(SphereIntersect, BehindTheRayMisses) {
    // Sphere spans z in [-10,10]; the ray starts at z=20 going +z: roots t = -30, -10.
    EXPECT_FALSE(trace(sphere(10), {0, 0, 20}, {0, 0, 1}).ok);
}

TEST(SphereIntersect, Translated) {
    // r=10 at (30,40,0), ray from the origin along (0.6,0.8,0) straight at the centre
    // (distance 50): t = 50 - 10 = 40, point 40*(0.6,0.8,0) = (24,32,0), normal -(0.6,0.8,0).
    EXPECT_HIT(trace(sphere(10, {30, 40, 0}), {0, 0, 0}, {0.6f, 0.8f, 0}), 40.0f, Vec3(24, 32, 0),
               Vec3(-0.6f, -0.8f, 0));
    // A rotation does not change a sphere.
    EXPECT_HIT(trace(sphere(10, {30, 40, 0}, {10, 20, 30}), {0, 0, 0}, {0.6f, 0.8f, 0}), 40.0f,
               Vec3(24, 32, 0), Vec3(-0.6f, -0.8f, 0));
    // Translated (0,0,100), r=2, ray x=1 along +z from the origin: z = 100 - sqrt(3).
    float dz = std::sqrt(3.0f);
    EXPECT_HIT(trace(sphere(2, {0, 0, 100}), {1, 0, 0}, {0, 0, 1}), 100.0f - dz, Vec3(1, 0, 100 - dz),
               Vec3(0.5f, 0, -dz / 2));
}

TEST(SphereIntersect, TMinTMaxHonoured) {
    Primitive s = sphere(10);
    Vec3 o{0, 0, -20}, d{0, 0, 1};  // entry t=10 at z=-10, exit t=30 at z=10
    EXPECT_FALSE(trace(s, o, d, 0, 10.0f).ok) << "tMax is exclusive and the exit is beyond it";
    EXPECT_FALSE(trace(s, o, d, 0, 9.5f).ok);
    EXPECT_HIT(trace(s, o, d, 0, 10.5f), 10.0f, Vec3(0, 0, -10), Vec3(0, 0, -1));
    // Past the entry the next crossing is the exit.
    EXPECT_HIT(trace(s, o, d, 15.0f), 30.0f, Vec3(0, 0, 10), Vec3(0, 0, 1));
    EXPECT_FALSE(trace(s, o, d, 30.5f).ok);
    EXPECT_FALSE(trace(s, o, d, 15.0f, 29.0f).ok);
}

// =========================== Table 3.3: cylinder ===========================
// Unless stated: r=5, h=10 at the origin, so the side is x^2+z^2 = 25 for |y| <= 5
// and the caps are y = +-5 with x^2+z^2 <= 25.

TEST(CylinderIntersect, SideHit) {
    // Along +x at y=z=0: x = -5, t = 15, normal (-1,0,0).
    EXPECT_HIT(trace(cylinder(5, 10), {-20, 0, 0}, {1, 0, 0}), 15.0f, Vec3(-5, 0, 0), Vec3(-1, 0, 0));
    // Along +z at x=3, y=2: 9 + z^2 = 25 -> z = -4, t = 16, normal (3,0,-4)/5 (no y part).
    EXPECT_HIT(trace(cylinder(5, 10), {3, 2, -20}, {0, 0, 1}), 16.0f, Vec3(3, 2, -4), Vec3(0.6f, 0, -0.8f));
}

TEST(CylinderIntersect, TopAndBottomCaps) {
    // Down the axis direction at (1,*,2): top cap y=5 after 15, normal +y.
    EXPECT_HIT(trace(cylinder(5, 10), {1, 20, 2}, {0, -1, 0}), 15.0f, Vec3(1, 5, 2), Vec3(0, 1, 0));
    // Upward from below: bottom cap y=-5, normal -y.
    EXPECT_HIT(trace(cylinder(5, 10), {1, -20, 2}, {0, 1, 0}), 15.0f, Vec3(1, -5, 2), Vec3(0, -1, 0));
    // Slanted into the top cap: from (0,20,-15) along (0,-0.8,0.6): y=5 after 15/0.8 = 18.75,
    // z = -15 + 0.6*18.75 = -3.75 (inside r=5).
    EXPECT_HIT(trace(cylinder(5, 10), {0, 20, -15}, {0, -0.8f, 0.6f}), 18.75f, Vec3(0, 5, -3.75f),
               Vec3(0, 1, 0));
}

TEST(CylinderIntersect, ParallelToAxis) {
    // Inside the radius (x^2+z^2 = 5 < 25): hits the cap (previous test); outside
    // (x=6): never within the radius -> miss.
    EXPECT_FALSE(trace(cylinder(5, 10), {6, 20, 0}, {0, -1, 0}).ok);
    EXPECT_FALSE(trace(cylinder(5, 10), {0, 20, -5.01f}, {0, -1, 0}).ok);
    // Exactly on the side's surface line (4,*,3): 16 + 9 = 25, the closed solid
    // still contains it -> hits the top cap on its rim.
    EXPECT_HIT(trace(cylinder(5, 10), {4, 20, 3}, {0, -1, 0}), 15.0f, Vec3(4, 5, 3), Vec3(0, 1, 0));
}

TEST(CylinderIntersect, RimHasNoGap) {
    // Diagonal ray through the rim point (-5,5,0): from (-15,15,0) along (1,-1,0)/sqrt2
    // it reaches x=-5 and y=5 at the same t = 10*sqrt2; either face may claim it.
    Hit h = trace(cylinder(5, 10), {-15, 15, 0}, {1, -1, 0});
    ASSERT_TRUE(h.ok) << "a ray into the rim slipped between cap and side";
    EXPECT_NEAR(h.t, 10 * kSqrt2, 1e-4f);
    EXPECT_VEC_NEAR(h.point, Vec3(-5, 5, 0), 1e-4f);
    EXPECT_TRUE(near(h.normal, {-1, 0, 0}, 1e-5f) || near(h.normal, {0, 1, 0}, 1e-5f)) << h.normal;
    // Grazing along the cap plane y=5: enters the side at x=-5 (t=15).
    EXPECT_HIT(trace(cylinder(5, 10), {-20, 5, 0}, {1, 0, 0}), 15.0f, Vec3(-5, 5, 0), Vec3(-1, 0, 0));
    EXPECT_FALSE(trace(cylinder(5, 10), {-20, 5.001f, 0}, {1, 0, 0}).ok);
    // Grazing the side line x=-5, z=0 going down: reaches the top cap at its rim.
    EXPECT_HIT(trace(cylinder(5, 10), {-5, 20, 0}, {0, -1, 0}), 15.0f, Vec3(-5, 5, 0), Vec3(0, 1, 0));
    EXPECT_FALSE(trace(cylinder(5, 10), {-5.001f, 20, 0}, {0, -1, 0}).ok);
    // Just inside both: a real hit on the cap near the rim.
    EXPECT_HIT(trace(cylinder(5, 10), {-4.999f, 20, 0}, {0, -1, 0}), 15.0f, Vec3(-4.999f, 5, 0),
               Vec3(0, 1, 0));
}

TEST(CylinderIntersect, OriginInsideReturnsExit) {
    // From the centre up the axis: top cap after 5.
    EXPECT_HIT(trace(cylinder(5, 10), {0, 0, 0}, {0, 1, 0}), 5.0f, Vec3(0, 5, 0), Vec3(0, 1, 0));
    // From (3,2,0) along +z: 9 + z^2 = 25 -> z = 4, normal (3,0,4)/5.
    EXPECT_HIT(trace(cylinder(5, 10), {3, 2, 0}, {0, 0, 1}), 4.0f, Vec3(3, 2, 4), Vec3(0.6f, 0, 0.8f));
}

TEST(CylinderIntersect, TMinTMaxHonoured) {
    // Along +x at y=z=0: entry t=15 (x=-5), exit t=25 (x=5).
    Primitive c = cylinder(5, 10);
    EXPECT_FALSE(trace(c, {-20, 0, 0}, {1, 0, 0}, 0, 14.9f).ok);
    EXPECT_HIT(trace(c, {-20, 0, 0}, {1, 0, 0}, 15.1f), 25.0f, Vec3(5, 0, 0), Vec3(1, 0, 0));
    EXPECT_FALSE(trace(c, {-20, 0, 0}, {1, 0, 0}, 25.1f).ok);
}

TEST(CylinderIntersect, RotatedRz90AxisAlongMinusX) {
    // rz=90 turns the local axis +y to world -x (x' = -y), so r=2, h=10 occupies
    // |x| <= 5, y^2+z^2 <= 4. World cap x=+5 is the local bottom cap (y_local = -5).
    Primitive c = cylinder(2, 10, {}, {0, 0, 90});
    // Along -x at (.,1,0): cap x=5 after 15, outward normal +x.
    EXPECT_HIT(trace(c, {20, 1, 0}, {-1, 0, 0}), 15.0f, Vec3(5, 1, 0), Vec3(1, 0, 0));
    // Along +x: cap x=-5, normal -x.
    EXPECT_HIT(trace(c, {-20, 0, 1}, {1, 0, 0}), 15.0f, Vec3(-5, 0, 1), Vec3(-1, 0, 0));
    // Down at x=0: side y=2 after 18, normal +y.
    EXPECT_HIT(trace(c, {0, 20, 0}, {0, -1, 0}), 18.0f, Vec3(0, 2, 0), Vec3(0, 1, 0));
    // Down at x=4.9 (within |x|<=5) hits; at x=6 (past the cap) misses, although an
    // unrotated r=2,h=10 cylinder would not contain x=4.9 at all.
    EXPECT_HIT(trace(c, {4.9f, 20, 0}, {0, -1, 0}), 18.0f, Vec3(4.9f, 2, 0), Vec3(0, 1, 0));
    EXPECT_FALSE(trace(c, {6, 20, 0}, {0, -1, 0}).ok);
    // Parallel to the axis outside the radius: y=3 > 2.
    EXPECT_FALSE(trace(c, {20, 3, 0}, {-1, 0, 0}).ok);
}

TEST(CylinderIntersect, RotatedRz45) {
    // rz=45: axis a = Rz45 (0,1,0) = (-sin45, cos45, 0) = (-s, s, 0), s = sqrt(1/2).
    // Ray along +x on the world x axis: point (x,0,0) has axial part -x s and
    // perpendicular part (x,0,0) - (-x s)(-s,s,0) = (x/2, x/2, 0), length |x|/sqrt2.
    // r=2 -> x = -2 sqrt2 (axial coordinate 2 <= h/2 = 5), t = 20 - 2 sqrt2,
    // normal (-s,-s,0).
    Primitive c = cylinder(2, 10, {}, {0, 0, 45});
    EXPECT_HIT(trace(c, {-20, 0, 0}, {1, 0, 0}), 20 - 2 * kSqrt2, Vec3(-2 * kSqrt2, 0, 0),
               Vec3(-kSqrtHalf, -kSqrtHalf, 0));
}

TEST(CylinderIntersect, TranslatedAndRotated) {
    // r=2, h=10 at (10,0,30) with rx=90: axis Rx90 (0,1,0) = (0,0,1), so the solid is
    // (x-10)^2 + y^2 <= 4, 25 <= z <= 35.
    Primitive c = cylinder(2, 10, {10, 0, 30}, {90, 0, 0});
    // From (10,0,0) along +z: cap z=25 after 25, normal -z.
    EXPECT_HIT(trace(c, {10, 0, 0}, {0, 0, 1}), 25.0f, Vec3(10, 0, 25), Vec3(0, 0, -1));
    // From (10,-20,34) along +y: side y=-2 after 18, normal -y. (Unrotated, the
    // point (10,*,34) would be 4 > r from the axis and miss.)
    EXPECT_HIT(trace(c, {10, -20, 34}, {0, 1, 0}), 18.0f, Vec3(10, -2, 34), Vec3(0, -1, 0));
    // z=36 is beyond the cap z=35.
    EXPECT_FALSE(trace(c, {10, -20, 36}, {0, 1, 0}).ok);
    // From (-10,0,30) along +x: (x-10)^2 = 4 -> x = 8 after 18, normal -x.
    EXPECT_HIT(trace(c, {-10, 0, 30}, {1, 0, 0}), 18.0f, Vec3(8, 0, 30), Vec3(-1, 0, 0));
}

// ============================== Table 3.4: box =============================
// Unless stated: size (4,6,10) at the origin, i.e. |x|<=2, |y|<=3, |z|<=5.

struct FaceCase {
    Vec3 origin, direction;
    float t;
    Vec3 point, normal;
};

TEST(BoxIntersect, EachFaceWithItsNormal) {
    const FaceCase cases[] = {
        {{10, 1, 2}, {-1, 0, 0}, 8, {2, 1, 2}, {1, 0, 0}},    // +x face x=2: t = 10-2
        {{-10, 1, 2}, {1, 0, 0}, 8, {-2, 1, 2}, {-1, 0, 0}},  // -x face
        {{1, 10, 2}, {0, -1, 0}, 7, {1, 3, 2}, {0, 1, 0}},    // +y face y=3: t = 10-3
        {{1, -10, 2}, {0, 1, 0}, 7, {1, -3, 2}, {0, -1, 0}},  // -y face
        {{1, 2, 10}, {0, 0, -1}, 5, {1, 2, 5}, {0, 0, 1}},    // +z face z=5: t = 10-5
        {{1, 2, -10}, {0, 0, 1}, 5, {1, 2, -5}, {0, 0, -1}},  // -z face
    };
    for (const FaceCase& c : cases) {
        SCOPED_TRACE(::testing::Message() << "origin " << c.origin << " dir " << c.direction);
        EXPECT_HIT(trace(box({4, 6, 10}), c.origin, c.direction), c.t, c.point, c.normal);
    }
    // Oblique from (0,11,0) along (0.6,-0.8,0): at y=3, t=10 and x=6 > 2; at x=2, t=10/3
    // and y = 11-8/3 > 3: never inside both slabs -> miss.
    EXPECT_FALSE(trace(box({4, 6, 10}), {0, 11, 0}, {0.6f, -0.8f, 0}).ok);
    // Oblique from (-1.5,7,0) along (0.6,-0.8,0): already inside the x and z slabs; y=3
    // after 4/0.8 = 5, where x = -1.5 + 0.6*5 = 1.5 <= 2: a +y hit.
    EXPECT_HIT(trace(box({4, 6, 10}), {-1.5f, 7, 0}, {0.6f, -0.8f, 0}), 5.0f, Vec3(1.5f, 3, 0),
               Vec3(0, 1, 0));
}

TEST(BoxIntersect, RayAlongAnEdge) {
    // The line y=3, z=5 is the edge between the +y and +z faces. Running along it in +x,
    // the first point of the closed box is the corner (-2,3,5), reached through x=-2.
    EXPECT_HIT(trace(box({4, 6, 10}), {-10, 3, 5}, {1, 0, 0}), 8.0f, Vec3(-2, 3, 5), Vec3(-1, 0, 0));
    // Just outside either face it misses.
    EXPECT_FALSE(trace(box({4, 6, 10}), {-10, 3.001f, 5}, {1, 0, 0}).ok);
    EXPECT_FALSE(trace(box({4, 6, 10}), {-10, 3, 5.001f}, {1, 0, 0}).ok);
    // Just inside both: an ordinary -x hit.
    EXPECT_HIT(trace(box({4, 6, 10}), {-10, 2.999f, 4.999f}, {1, 0, 0}), 8.0f, Vec3(-2, 2.999f, 4.999f),
               Vec3(-1, 0, 0));
}

TEST(BoxIntersect, RayAcrossAnEdgeHasNoGap) {
    // From (12,13,0) along (-1,-1,0)/sqrt2: reaches x=2 and y=3 together at t = 10 sqrt2,
    // at the +x/+y edge point (2,3,0). It must hit one of the two faces.
    Hit h = trace(box({4, 6, 10}), {12, 13, 0}, {-1, -1, 0});
    ASSERT_TRUE(h.ok) << "a ray into the edge slipped between the faces";
    EXPECT_NEAR(h.t, 10 * kSqrt2, 1e-4f);
    EXPECT_VEC_NEAR(h.point, Vec3(2, 3, 0), 1e-4f);
    EXPECT_TRUE(near(h.normal, {1, 0, 0}, 1e-5f) || near(h.normal, {0, 1, 0}, 1e-5f)) << h.normal;
    // The same through the (-2,-3,-5) corner: from (-12,-13,-15) along (1,1,1)/sqrt3,
    // t = 10 sqrt3; the normal is one of -x, -y, -z.
    Hit k = trace(box({4, 6, 10}), {-12, -13, -15}, {1, 1, 1});
    ASSERT_TRUE(k.ok) << "a ray into the corner slipped through";
    EXPECT_NEAR(k.t, 10 * std::sqrt(3.0f), 1e-4f);
    EXPECT_VEC_NEAR(k.point, Vec3(-2, -3, -5), 1e-4f);
    EXPECT_TRUE(near(k.normal, {-1, 0, 0}, 1e-5f) || near(k.normal, {0, -1, 0}, 1e-5f) ||
                near(k.normal, {0, 0, -1}, 1e-5f))
        << k.normal;
}

TEST(BoxIntersect, ParallelToAFace) {
    // Along +x inside the y and z slabs: -x face after 8.
    EXPECT_HIT(trace(box({4, 6, 10}), {-10, 0, 0}, {1, 0, 0}), 8.0f, Vec3(-2, 0, 0), Vec3(-1, 0, 0));
    // Outside the y slab (3.5 > 3) it never enters.
    EXPECT_FALSE(trace(box({4, 6, 10}), {-10, 3.5f, 0}, {1, 0, 0}).ok);
    EXPECT_FALSE(trace(box({4, 6, 10}), {-10, 0, -5.5f}, {1, 0, 0}).ok);
    // In the plane of the +y face: the closed box contains that face; first point x=-2.
    EXPECT_HIT(trace(box({4, 6, 10}), {-10, 3, 0}, {1, 0, 0}), 8.0f, Vec3(-2, 3, 0), Vec3(-1, 0, 0));
}

TEST(BoxIntersect, OriginInsideReturnsExit) {
    // From the centre along +z: exit z=5 after 5.
    EXPECT_HIT(trace(box({4, 6, 10}), {0, 0, 0}, {0, 0, 1}), 5.0f, Vec3(0, 0, 5), Vec3(0, 0, 1));
    // From (1,1,1) along (0.6,0.8,0): x=2 after 1/0.6 = 5/3, y=3 after 2/0.8 = 2.5, so the
    // exit is x=2 at t=5/3, y = 1 + 0.8*5/3 = 7/3.
    EXPECT_HIT(trace(box({4, 6, 10}), {1, 1, 1}, {0.6f, 0.8f, 0}), 5.0f / 3, Vec3(2, 7.0f / 3, 1),
               Vec3(1, 0, 0));
}

TEST(BoxIntersect, TMinTMaxHonoured) {
    // Along +z from (1,2,-10): entry t=5 (z=-5), exit t=15 (z=5).
    Primitive b = box({4, 6, 10});
    EXPECT_FALSE(trace(b, {1, 2, -10}, {0, 0, 1}, 0, 4.9f).ok);
    EXPECT_HIT(trace(b, {1, 2, -10}, {0, 0, 1}, 0, 5.1f), 5.0f, Vec3(1, 2, -5), Vec3(0, 0, -1));
    EXPECT_HIT(trace(b, {1, 2, -10}, {0, 0, 1}, 5.1f), 15.0f, Vec3(1, 2, 5), Vec3(0, 0, 1));
    EXPECT_FALSE(trace(b, {1, 2, -10}, {0, 0, 1}, 5.1f, 14.9f).ok);
    EXPECT_FALSE(trace(b, {1, 2, -10}, {0, 0, 1}, 15.1f).ok);
}

TEST(BoxIntersect, RotatedRy45) {
    // ry=45: local x -> (cos45, 0, -sin45) = (s,0,-s), local z -> (s,0,s), s = sqrt(1/2).
    // A world point (0,0,z) has local x = -z s and local z = z s; |x_l| <= 2 gives
    // |z| <= 2 sqrt2 (the tighter of 2 sqrt2 and 5 sqrt2). Entering from -z:
    // z = -2 sqrt2, t = 20 - 2 sqrt2, on the local +x face (x_l = 2): normal (s,0,-s).
    Primitive b = box({4, 6, 10}, {}, {0, 45, 0});
    EXPECT_HIT(trace(b, {0, 0, -20}, {0, 0, 1}), 20 - 2 * kSqrt2, Vec3(0, 0, -2 * kSqrt2),
               Vec3(kSqrtHalf, 0, -kSqrtHalf));
    // An axis-aligned box of the same size would be hit at z=-5 instead.
    // From +x along -x: (x,0,0) has x_l = x s, z_l = x s -> x = 2 sqrt2, normal (s,0,-s) again.
    EXPECT_HIT(trace(b, {20, 0, 0}, {-1, 0, 0}), 20 - 2 * kSqrt2, Vec3(2 * kSqrt2, 0, 0),
               Vec3(kSqrtHalf, 0, -kSqrtHalf));
}

TEST(BoxIntersect, RotatedAndTranslated) {
    // Same ry=45 box at (5,0,5). From (5,0,5) + 20 (s,0,s) back along -(s,0,s), i.e. down
    // the local z axis: local z=5 face after 20-5 = 15, point (5,0,5) + 5(s,0,s), normal (s,0,s).
    Primitive b = box({4, 6, 10}, {5, 0, 5}, {0, 45, 0});
    Vec3 axisZ{kSqrtHalf, 0, kSqrtHalf};
    EXPECT_HIT(trace(b, Vec3(5, 0, 5) + axisZ * 20, -axisZ), 15.0f, Vec3(5, 0, 5) + axisZ * 5, axisZ);
    // Straight down at (5,*,5): top face y=3 after 17.
    EXPECT_HIT(trace(b, {5, 20, 5}, {0, -1, 0}), 17.0f, Vec3(5, 3, 5), Vec3(0, 1, 0));
}

// ======================= Properties (seeded, pbrt style) ===================

struct Sample {
    Vec3 local, localNormal;
    float edgeMargin;  ///< distance (local) from the sample to the nearest edge or rim
};

/// A random point on the surface of the primitive, in its local frame.
Sample sampleSurface(ShapeKind kind, Vec3 size, std::mt19937& rng) {
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    const float twoPi = float(2 * kPi);
    switch (kind) {
        case ShapeKind::Sphere: {
            float z = 2 * u01(rng) - 1, phi = twoPi * u01(rng), s = std::sqrt(std::max(0.0f, 1 - z * z));
            Vec3 n{s * std::cos(phi), s * std::sin(phi), z};
            return {n * size.x, n, size.x};
        }
        case ShapeKind::Cylinder: {
            float r = size.x, hh = size.y / 2;
            float side = 2 * r * hh * 2, caps = 2 * r * r;  // areas / pi
            float phi = twoPi * u01(rng);
            Vec3 radial{std::cos(phi), 0, std::sin(phi)};
            if (u01(rng) * (side + caps) < side) {
                float y = (2 * u01(rng) - 1) * hh;
                return {radial * r + Vec3(0, y, 0), radial, hh - std::fabs(y)};
            }
            float rho = r * std::sqrt(u01(rng)), sign = u01(rng) < 0.5f ? -1.0f : 1.0f;
            return {radial * rho + Vec3(0, sign * hh, 0), {0, sign, 0}, r - rho};
        }
        case ShapeKind::Box: {
            Vec3 h = size * 0.5f;
            float area[3] = {h.y * h.z, h.z * h.x, h.x * h.y};
            float pick = u01(rng) * (area[0] + area[1] + area[2]);
            int axis = pick < area[0] ? 0 : (pick < area[0] + area[1] ? 1 : 2);
            float sign = u01(rng) < 0.5f ? -1.0f : 1.0f;
            Vec3 q, n;
            float margin = kInfinity;
            for (int i = 0; i < 3; ++i) {
                if (i == axis) {
                    q[i] = sign * h[i];
                    n[i] = sign;
                } else {
                    q[i] = (2 * u01(rng) - 1) * h[i];
                    margin = std::min(margin, h[i] - std::fabs(q[i]));
                }
            }
            return {q, n, margin};
        }
    }
    return {};
}

/// Signed distance-like residual of the implicit surface in local coordinates: 0 on it.
float surfaceResidual(ShapeKind kind, Vec3 size, Vec3 q) {
    switch (kind) {
        case ShapeKind::Sphere:
            return length(q) - size.x;
        case ShapeKind::Cylinder:
            return std::max(std::sqrt(q.x * q.x + q.z * q.z) - size.x, std::fabs(q.y) - size.y / 2);
        case ShapeKind::Box: {
            Vec3 h = size * 0.5f;
            return std::max({std::fabs(q.x) - h.x, std::fabs(q.y) - h.y, std::fabs(q.z) - h.z});
        }
    }
    return 0;
}

Vec3 randomUnit(std::mt19937& rng) {
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    float z = 2 * u01(rng) - 1, phi = float(2 * kPi) * u01(rng), s = std::sqrt(std::max(0.0f, 1 - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
}

struct RandomShape {
    ShapeKind kind;
    Vec3 size;
    Transform worldFromLocal;
    Primitive prim;
    float extent;  ///< largest dimension, for tolerances
};

RandomShape randomShape(std::mt19937& rng) {
    std::uniform_real_distribution<float> u01(0.0f, 1.0f), angle(-180.0f, 180.0f), coord(-50.0f, 50.0f);
    auto dim = [&] { return 0.5f + 19.5f * u01(rng); };
    RandomShape s;
    s.kind = ShapeKind(int(u01(rng) * 3) % 3);
    switch (s.kind) {
        case ShapeKind::Sphere:
            s.size = {dim(), 0, 0};
            break;
        case ShapeKind::Cylinder:
            s.size = {dim(), 2 * dim(), 0};
            break;
        case ShapeKind::Box:
            s.size = {2 * dim(), 2 * dim(), 2 * dim()};
            break;
    }
    s.worldFromLocal =
        Transform::fromPose({coord(rng), coord(rng), coord(rng)}, {angle(rng), angle(rng), angle(rng)});
    s.prim = makePrimitive(s.kind, s.size, s.worldFromLocal);
    s.extent = std::max({s.size.x, s.size.y, s.size.z});
    return s;
}

const char* kindName(ShapeKind k) {
    return k == ShapeKind::Sphere ? "sphere" : (k == ShapeKind::Cylinder ? "cylinder" : "box");
}

TEST(IntersectProperty, RaysTowardSurfacePointsHitThem) {
    const std::uint32_t seed = test::testSeed(1234567u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    int checkedNormals = 0;
    for (int n = 0; n < 20000; ++n) {
        RandomShape s = randomShape(rng);
        Sample smp = sampleSurface(s.kind, s.size, rng);
        Vec3 p = s.worldFromLocal.applyToPoint(smp.local);
        Vec3 nWorld = s.worldFromLocal.applyToVector(smp.localNormal);
        // The origin lies in the open half-space beyond the supporting plane at p, so for
        // a convex solid the segment to p is outside it and p is the first hit.
        Vec3 w;
        do w = randomUnit(rng);
        while (dot(w, nWorld) < 0.1f);
        float dist = 0.5f + 100.0f * u01(rng);
        Ray ray{p + w * dist, -w};
        // Float error grows with coordinate size: |p| <= ~100, dist <= ~100.
        float scale = 1 + length(ray.origin - s.prim.centre) + s.extent;
        float tol = 2e-5f * scale;
        SCOPED_TRACE(::testing::Message() << "case " << n << ' ' << kindName(s.kind) << " size " << s.size
                                          << " centre " << s.prim.centre << " origin " << ray.origin
                                          << " dir " << ray.direction << " target " << p);
        float t;
        Face face;
        ASSERT_TRUE(intersectPrimitive(s.prim, ray, 0, kInfinity, t, face));
        EXPECT_NEAR(t, dist, tol);
        Vec3 hit = ray.origin + ray.direction * t;
        // The hit satisfies the implicit equation in local coordinates (independent of prim.axes).
        Vec3 q = s.worldFromLocal.inverseRigid().applyToPoint(hit);
        EXPECT_NEAR(surfaceResidual(s.kind, s.size, q), 0.0f, tol);
        // Normal: unit, facing the incoming ray (outward at an entry), and the true one
        // away from edges where the face is unambiguous.
        Vec3 normal = primitiveNormal(s.prim, hit, face);
        EXPECT_NEAR(length(normal), 1.0f, 1e-5f);
        EXPECT_LT(dot(normal, ray.direction), 0.0f);
        if (smp.edgeMargin > 1e-3f * s.extent) {
            ++checkedNormals;
            EXPECT_VEC_NEAR(normal, nWorld, 1e-3f);
        }
        // Re-intersecting from just outside along the same ray finds the same point.
        float eps = 1e-2f * s.extent;
        Ray again{hit - ray.direction * eps, ray.direction};
        float t2;
        Face face2;
        ASSERT_TRUE(intersectPrimitive(s.prim, again, 0, kInfinity, t2, face2));
        EXPECT_NEAR(t2, eps, tol);
        EXPECT_VEC_NEAR(again.origin + again.direction * t2, hit, tol);
        // tMax just short of the surface: nothing (the origin is outside).
        float gap = 1e-3f * dist + 10 * tol;
        EXPECT_FALSE(intersectPrimitive(s.prim, ray, 0, dist - gap, t2, face2)) << "t " << t2;
        // tMin just past the entry: whatever comes back (the exit) lies in (tMin, tMax).
        float tMin = dist + gap, tMax = dist + 2 * s.extent * 3;
        if (intersectPrimitive(s.prim, ray, tMin, tMax, t2, face2)) {
            EXPECT_GT(t2, tMin);
            EXPECT_LT(t2, tMax);
            Vec3 q2 = s.worldFromLocal.inverseRigid().applyToPoint(ray.origin + ray.direction * t2);
            EXPECT_NEAR(surfaceResidual(s.kind, s.size, q2), 0.0f, tol);
            // The exit normal points along the ray (outward at an exit).
            EXPECT_GT(dot(primitiveNormal(s.prim, ray.origin + ray.direction * t2, face2), ray.direction),
                      0.0f);
        }
        if (HasFailure()) return;
    }
    EXPECT_GT(checkedNormals, 15000);  // most samples are away from edges
}

TEST(IntersectProperty, RaysFromInsideHitTheExit) {
    const std::uint32_t seed = test::testSeed(424242u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    for (int n = 0; n < 5000; ++n) {
        RandomShape s = randomShape(rng);
        Sample smp = sampleSurface(s.kind, s.size, rng);
        // An interior point strictly between the centre and the sample; the ray from it
        // toward the sample leaves a convex solid exactly there.
        float f = 0.1f + 0.8f * u01(rng);
        Vec3 inside = s.worldFromLocal.applyToPoint(smp.local * f);
        Vec3 p = s.worldFromLocal.applyToPoint(smp.local);
        float dist = length(p - inside);
        Ray ray{inside, (p - inside) / dist};
        float tol = 2e-5f * (1 + length(ray.origin) + s.extent) * 10;
        SCOPED_TRACE(::testing::Message() << "case " << n << ' ' << kindName(s.kind) << " size " << s.size
                                          << " origin " << ray.origin << " target " << p);
        float t;
        Face face;
        ASSERT_TRUE(intersectPrimitive(s.prim, ray, 0, kInfinity, t, face));
        EXPECT_NEAR(t, dist, tol);
        Vec3 hit = ray.origin + ray.direction * t;
        EXPECT_GT(dot(primitiveNormal(s.prim, hit, face), ray.direction), 0.0f);  // outward at the exit
        if (HasFailure()) return;
    }
}

TEST(IntersectProperty, LinesOutsideTheBoundingSphereMiss) {
    const std::uint32_t seed = test::testSeed(31337u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    for (int n = 0; n < 5000; ++n) {
        RandomShape s = randomShape(rng);
        // Every local point is within |half| of the centre (sphere r; cylinder
        // sqrt(r^2 + (h/2)^2); box the half diagonal).
        float radius = s.kind == ShapeKind::Sphere ? s.size.x
                       : s.kind == ShapeKind::Cylinder
                           ? std::sqrt(s.size.x * s.size.x + s.size.y * s.size.y / 4)
                           : length(s.size * 0.5f);
        Vec3 d = randomUnit(rng);
        Vec3 perp = normalize(cross(d, randomUnit(rng)));
        Vec3 closest = s.prim.centre + perp * (radius * (1.01f + u01(rng)));
        Ray ray{closest - d * (50 * u01(rng)), d};
        float t;
        Face face;
        EXPECT_FALSE(intersectPrimitive(s.prim, ray, 0, kInfinity, t, face))
            << kindName(s.kind) << " size " << s.size << " t " << t << " seed " << seed << " case " << n;
        if (HasFailure()) return;
    }
}

TEST(IntersectProperty, IntervalContainsOnlyInsidePoints) {
    // primitiveInterval: points strictly between enter and exit are inside the solid.
    const std::uint32_t seed = test::testSeed(2718u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    int hits = 0;
    for (int n = 0; n < 5000; ++n) {
        RandomShape s = randomShape(rng);
        Vec3 target = s.prim.centre + randomUnit(rng) * (s.extent * u01(rng));
        Vec3 origin = target + randomUnit(rng) * (s.extent * 3);
        Ray ray{origin, normalize(target - origin)};
        Interval iv;
        if (!primitiveInterval(s.prim, ray, iv)) continue;
        ++hits;
        EXPECT_LE(iv.enter, iv.exit);
        Transform inv = s.worldFromLocal.inverseRigid();
        float tol = 2e-5f * (1 + length(origin - s.prim.centre) + s.extent) * 10;
        for (float f : {0.25f, 0.5f, 0.75f}) {
            float t = iv.enter + f * (iv.exit - iv.enter);
            EXPECT_LE(surfaceResidual(s.kind, s.size, inv.applyToPoint(ray.origin + ray.direction * t)), tol);
        }
        EXPECT_NEAR(surfaceResidual(s.kind, s.size, inv.applyToPoint(ray.origin + ray.direction * iv.enter)),
                    0, tol);
        EXPECT_NEAR(surfaceResidual(s.kind, s.size, inv.applyToPoint(ray.origin + ray.direction * iv.exit)),
                    0, tol);
        if (HasFailure()) return;
    }
    EXPECT_GT(hits, 1000);
}

}  // namespace
}  // namespace f2
