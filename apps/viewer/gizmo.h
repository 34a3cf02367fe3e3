#pragma once
/// The move and turn handles drawn over the picture for the selected target,
/// as pure geometry: where they are in the picture (pixels of a camera's
/// image), which one a point hits, and the key pose a drag from one point to
/// another makes. No widgets, so the numbers a drag writes are unit-tested.
#include <QPointF>
#include <array>
#include <optional>
#include <vector>

#include "core/math/transform.h"
#include "core/render/camera.h"
#include "core/scene/scene_desc.h"

namespace f2::viewer {

/// Where a target's key pose is read (SPEC 6, 9.2, 10.1): its world frame is
/// `parent · translate(pose.position) · rest · rotate(pose.rotation)`. An
/// object: `parent` is the frame it rides on (the world when it rides on
/// nothing) and `rest` none. A part: `parent` is its parent's frame moved to
/// its pivot, and `rest` its rest rotation, so its key turns it about its pivot.
/// The handles are at `handle` in the target's frame: its origin, or a named
/// light's written position.
struct GizmoFrame {
    Transform parent;
    Mat3 rest;
    Pose pose;  ///< the key's six numbers at the frame
    Vec3 handle;

    /// The target's world frame for `key`.
    Transform world(const Pose& key) const;
    Transform world() const { return world(pose); }
    /// Where the handles are in the world for `key`: turns are about this point.
    Vec3 centre(const Pose& key) const { return world(key).applyToPoint(handle); }
    Vec3 centre() const { return centre(pose); }
};

enum class GizmoMode { Move, Turn };
/// A handle: an axis (an arrow, or a ring about it), or the square that moves
/// in the screen plane.
enum class GizmoHandle { X, Y, Z, Screen };

/// The handles of one frame seen through one camera.
class Gizmo {
   public:
    /// `localAxes`: the target's own axes, else its parent's (the axes its
    /// key's position is written in).
    Gizmo(const Camera& camera, const GizmoFrame& frame, GizmoMode mode, bool localAxes);

    /// The target's origin is in front of the eye: the handles can be drawn.
    bool visible() const { return visible_; }
    QPointF centre() const { return centre_; }
    /// The world direction of axis `axis` (0: x, 1: y, 2: z).
    Vec3 axis(int axis) const;
    /// The arrow of axis `axis` ends here (pixels).
    QPointF arrowEnd(int axis) const { return arrowEnds_[std::size_t(axis)]; }
    /// The ring about axis `axis`, as a closed polyline (pixels); empty where it
    /// goes behind the eye.
    const std::vector<QPointF>& ring(int axis) const { return rings_[std::size_t(axis)]; }
    /// The arrows' length and the rings' radius on screen (pixels): kArmPixels,
    /// less in a small picture.
    double armPixels() const { return arm_; }
    /// Half the side of the screen-plane square (pixels).
    double squareHalf() const { return arm_ * 0.12; }
    /// The handle at `point` (pixels), if any: the nearest within kHitPixels.
    std::optional<GizmoHandle> hit(QPointF point) const;

    GizmoMode mode() const { return mode_; }
    bool localAxes() const { return local_; }
    const Camera& camera() const { return camera_; }
    const GizmoFrame& frame() const { return frame_; }
    /// World units per pixel at the target's origin.
    double unitsPerPixel() const { return unitsPerPixel_; }

    static constexpr double kArmPixels = 60;
    /// At most this fraction of the picture's smaller side.
    static constexpr double kArmFraction = 0.2;
    /// How near a handle a press must be to take it.
    static constexpr double kHitPixels = 6;
    /// Ctrl: moves by multiples of this (scene units), turns by multiples of kSnapDegrees.
    static constexpr double kSnapUnits = 10;
    static constexpr double kSnapDegrees = 15;

   private:
    Camera camera_;
    GizmoFrame frame_;
    GizmoMode mode_;
    bool local_;
    bool visible_ = false;
    Transform world_;
    QPointF centre_;
    double unitsPerPixel_ = 1;
    double arm_ = kArmPixels;
    std::array<QPointF, 3> arrowEnds_;
    std::array<std::vector<QPointF>, 3> rings_;
};

/// One drag of a handle: the key pose for each mouse position since the press.
class GizmoDrag {
   public:
    GizmoDrag(const Gizmo& gizmo, GizmoHandle handle, QPointF pressedAt);

    /// The key pose with the mouse at `point`, its numbers rounded to
    /// kPrecision (what a person would type; the text and the preview then
    /// agree); `snap` (Ctrl) rounds a move to multiples of kSnapUnits and a
    /// turn to multiples of kSnapDegrees.
    Pose update(QPointF point, bool snap);
    static constexpr double kPrecision = 0.01;
    GizmoHandle handle() const { return handle_; }
    const Gizmo& gizmo() const { return gizmo_; }

   private:
    Pose unrounded(QPointF point, bool snap);
    /// Where along the dragged axis (world units from the origin) the ray through `point` passes nearest.
    std::optional<double> alongAxis(QPointF point) const;
    /// Where the ray through `point` meets the screen plane through the origin.
    std::optional<Vec3> onScreenPlane(QPointF point) const;
    Pose moved(Vec3 worldDelta, bool snap) const;
    Pose turned(double degrees) const;

    Gizmo gizmo_;
    GizmoHandle handle_;
    QPointF pressedAt_;
    QPointF last_;
    double turnedDegrees_ = 0;  // accumulated over the moves: a drag may go round more than once
};

/// The rotation of `degrees` about the unit axis `axis` (right-handed).
Mat3 rotationAbout(Vec3 axis, double degrees);
/// Angles for `rotation` (rotationFromEulerDegrees's order), of all the
/// triples that make it the one nearest `near`: a drag changes the numbers
/// it turns, not all three.
Vec3 eulerDegreesNear(const Mat3& rotation, Vec3 near);

}  // namespace f2::viewer
