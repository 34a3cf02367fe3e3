#pragma once
/// The frame's primitives as one Embree user geometry: exact analytic
/// intersection of spheres, closed cylinders and boxes (SPEC 4), computed over
/// all lanes of an Embree ray packet at once.
#include <embree3/rtcore.h>

#include <cmath>
#include <vector>

#include "prims_file.h"

namespace f2::peer {

/// Which surface of a shape a ray crossed; decides the normal.
enum Face : int { kCurved = 0, kCap = 1, kSlabX = 2, kSlabY = 3, kSlabZ = 4 };

/// What the intersection callbacks read of one primitive, world space.
struct alignas(64) Shape {
    float centre[3];
    float half[3];     ///< sphere: r; cylinder: r, h/2, r; box: half sides
    float axes[3][3];  ///< rows of localFromWorld (columns of worldFromLocal)
    ShapeKind kind;
};

Shape makeShape(const PrimRecord& record);

/// Unit outward normal at world point `p`, on face `face` of `s`.
inline void shapeNormal(const Shape& s, const float p[3], int face, float n[3]) {
    const float local[3] = {p[0] - s.centre[0], p[1] - s.centre[1], p[2] - s.centre[2]};
    if (face == kCurved) {
        float v[3] = {local[0], local[1], local[2]};
        if (s.kind == ShapeKind::Cylinder) {
            const float* a = s.axes[1];
            float along = local[0] * a[0] + local[1] * a[1] + local[2] * a[2];
            for (int i = 0; i < 3; ++i) v[i] = local[i] - a[i] * along;
        }
        float scale = 1.0f / std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        for (int i = 0; i < 3; ++i) n[i] = v[i] * scale;
        return;
    }
    const float* a = s.axes[face == kCap ? 1 : face - kSlabX];
    float sign = local[0] * a[0] + local[1] * a[1] + local[2] * a[2] >= 0 ? 1.0f : -1.0f;
    for (int i = 0; i < 3; ++i) n[i] = sign * a[i];
}

/// How the BVH follows the primitives: built once, or updated every frame.
enum class BuildMode { Static, Low, Medium, High, Refit };

/// An Embree scene holding every primitive of a frame in one user geometry.
/// A shadow ray's `id` names the primitive it must skip (the convex shape it
/// leaves from outside), or kNoSkip.
class UserShapeScene {
public:
    static constexpr unsigned kNoSkip = RTC_INVALID_GEOMETRY_ID;

    UserShapeScene(RTCDevice device, BuildMode mode);
    ~UserShapeScene();
    UserShapeScene(const UserShapeScene&) = delete;
    UserShapeScene& operator=(const UserShapeScene&) = delete;

    /// Takes the frame's primitives (as an animation hands over each frame's).
    void setPrimitives(const std::vector<PrimRecord>& prims);
    /// Builds or refits the BVH over the primitives last set.
    void commit();

    RTCScene handle() const { return scene_; }
    const Shape& shape(unsigned id) const { return shapes_[id]; }

private:
    RTCScene scene_ = nullptr;
    RTCGeometry geometry_ = nullptr;
    std::vector<Shape> shapes_;
};

}  // namespace f2::peer
