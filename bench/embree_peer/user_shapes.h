#pragma once
/// The frame's primitives as one Embree user geometry: exact analytic
/// intersection of spheres, closed cylinders and boxes (SPEC 4), computed over
/// all lanes of an Embree ray packet at once.
#include <embree3/rtcore.h>

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
