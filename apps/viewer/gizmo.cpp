#include "gizmo.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace f2::viewer {

namespace {

constexpr int kRingSegments = 48;

double distanceToSegment(QPointF p, QPointF a, QPointF b) {
    const QPointF ab = b - a;
    const double length2 = QPointF::dotProduct(ab, ab);
    const double t = length2 > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    const QPointF d = p - (a + t * ab);
    return std::hypot(d.x(), d.y());
}

double snapped(double value, double step) { return std::round(value / step) * step; }

/// `degrees` plus the multiple of 360 that brings it nearest `near`.
double wrappedNear(double degrees, double near) {
    return degrees + 360.0 * std::round((near - degrees) / 360.0);
}

}  // namespace

Transform GizmoFrame::world(const Pose& key) const {
    return parent * Transform{rest * rotationFromEulerDegrees(key.rotation), key.position};
}

Mat3 rotationAbout(Vec3 axis, double degrees) {
    const Vec3 u = normalize(axis);
    const double a = degrees * kPi / 180.0, c = std::cos(a), s = std::sin(a), t = 1 - c;
    const double x = u.x, y = u.y, z = u.z;
    Mat3 m;
    m.row[0] = {float(t * x * x + c), float(t * x * y - s * z), float(t * x * z + s * y)};
    m.row[1] = {float(t * x * y + s * z), float(t * y * y + c), float(t * y * z - s * x)};
    m.row[2] = {float(t * x * z - s * y), float(t * y * z + s * x), float(t * z * z + c)};
    return m;
}

Vec3 eulerDegreesNear(const Mat3& rotation, Vec3 near) {
    const Vec3 a = eulerDegreesFromRotation(rotation);
    // Rz(z) Ry(y) Rx(x) = Rz(z + 180) Ry(180 - y) Rx(x + 180): the other triple.
    const Vec3 candidates[2] = {a, {a.x + 180, 180 - a.y, a.z + 180}};
    Vec3 best;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (const Vec3& c : candidates) {
        const Vec3 w{float(wrappedNear(c.x, near.x)), float(wrappedNear(c.y, near.y)),
                     float(wrappedNear(c.z, near.z))};
        const double d = std::fabs(w.x - near.x) + std::fabs(w.y - near.y) + std::fabs(w.z - near.z);
        if (d < bestDistance) {
            bestDistance = d;
            best = w;
        }
    }
    return best;
}

Gizmo::Gizmo(const Camera& camera, const GizmoFrame& frame, GizmoMode mode, bool localAxes)
    : camera_(camera), frame_(frame), mode_(mode), local_(localAxes), world_(frame.world()) {
    const Vec3 origin = frame.centre();
    const Vec3 forward = camera.worldFromCamera.column(2);
    const double depth = dot(origin - camera.eye, forward);
    float px = 0, py = 0;
    visible_ = depth > 0 && camera.project(origin, px, py);
    if (!visible_) return;
    centre_ = {px, py};
    // A pixel at depth z spans z / (d · width) units (Camera::project).
    unitsPerPixel_ = depth / (double(camera.distance) * camera.width);
    arm_ = std::min(kArmPixels, kArmFraction * std::min(camera.width, camera.height));
    const float arm = float(arm_ * unitsPerPixel_);
    for (int i = 0; i < 3; ++i) {
        const Vec3 u = axis(i);
        arrowEnds_[std::size_t(i)] = camera.project(origin + u * arm, px, py) ? QPointF(px, py) : centre_;
        if (mode != GizmoMode::Turn) continue;
        // Two directions across the axis span its ring.
        const Vec3 a = normalize(cross(u, std::fabs(u.x) < 0.9f ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
        const Vec3 b = cross(u, a);
        std::vector<QPointF>& ring = rings_[std::size_t(i)];
        for (int k = 0; k < kRingSegments; ++k) {
            const double phi = 2 * kPi * k / kRingSegments;
            const Vec3 p = origin + (a * float(std::cos(phi)) + b * float(std::sin(phi))) * arm;
            if (!camera.project(p, px, py)) {
                ring.clear();
                break;
            }
            ring.emplace_back(px, py);
        }
    }
}

Vec3 Gizmo::axis(int axis) const {
    return normalize((local_ ? world_.linear : frame_.parent.linear).column(axis));
}

std::optional<GizmoHandle> Gizmo::hit(QPointF point) const {
    if (!visible_) return std::nullopt;
    const QPointF fromCentre = point - centre_;
    if (mode_ == GizmoMode::Move && std::fabs(fromCentre.x()) <= squareHalf() + 1 &&
        std::fabs(fromCentre.y()) <= squareHalf() + 1)
        return GizmoHandle::Screen;
    std::optional<GizmoHandle> best;
    double bestDistance = kHitPixels;
    for (int i = 0; i < 3; ++i) {
        double d = std::numeric_limits<double>::infinity();
        if (mode_ == GizmoMode::Move) {
            // An arrow seen end on has no direction to drag along.
            const QPointF arrow = arrowEnds_[std::size_t(i)] - centre_;
            if (std::hypot(arrow.x(), arrow.y()) >= 2 * kHitPixels)
                d = distanceToSegment(point, centre_, arrowEnds_[std::size_t(i)]);
        } else {
            const std::vector<QPointF>& ring = rings_[std::size_t(i)];
            for (std::size_t k = 0; k < ring.size(); ++k)
                d = std::min(d, distanceToSegment(point, ring[k], ring[(k + 1) % ring.size()]));
        }
        if (d <= bestDistance) {
            bestDistance = d;
            best = GizmoHandle(i);
        }
    }
    return best;
}

GizmoDrag::GizmoDrag(const Gizmo& gizmo, GizmoHandle handle, QPointF pressedAt)
    : gizmo_(gizmo), handle_(handle), pressedAt_(pressedAt), last_(pressedAt) {}

std::optional<double> GizmoDrag::alongAxis(QPointF point) const {
    // The nearest points of the axis line o + s·u and the ray e + t·v.
    const Ray ray = gizmo_.camera().rayThrough(float(point.x()), float(point.y()));
    const Vec3 u = gizmo_.axis(int(handle_));
    const Vec3 v = normalize(ray.direction);
    const Vec3 w = gizmo_.frame().centre() - ray.origin;
    const double b = dot(u, v), d = dot(u, w), e = dot(v, w);
    const double across = 1 - b * b;
    if (across < 1e-4) return std::nullopt;  // the axis runs along the ray
    return (b * e - d) / across;
}

std::optional<Vec3> GizmoDrag::onScreenPlane(QPointF point) const {
    const Ray ray = gizmo_.camera().rayThrough(float(point.x()), float(point.y()));
    const Vec3 forward = gizmo_.camera().worldFromCamera.column(2);
    const double along = dot(ray.direction, forward);
    if (along <= 0) return std::nullopt;
    const double t = dot(gizmo_.frame().centre() - ray.origin, forward) / along;
    return ray.origin + ray.direction * float(t);
}

Pose GizmoDrag::update(QPointF point, bool snap) {
    Pose pose = unrounded(point, snap);
    for (int i = 0; i < 3; ++i) {
        pose.position[i] = float(snapped(pose.position[i], kPrecision));
        pose.rotation[i] = float(snapped(pose.rotation[i], kPrecision));
    }
    return pose;
}

Pose GizmoDrag::unrounded(QPointF point, bool snap) {
    const Pose& start = gizmo_.frame().pose;
    if (gizmo_.mode() == GizmoMode::Turn) {
        const QPointF c = gizmo_.centre();
        const auto angle = [&](QPointF p) { return std::atan2(p.y() - c.y(), p.x() - c.x()) * 180 / kPi; };
        turnedDegrees_ += wrappedNear(angle(point) - angle(last_), 0);
        last_ = point;
        // On screen (y down) an angle grows clockwise. Seen from the eye, with
        // x right, y up and z away (SPEC 1), a positive turn about an axis
        // pointing away (+x toward +y about z) goes anticlockwise.
        const Vec3 forward = gizmo_.camera().worldFromCamera.column(2);
        const double sign = dot(gizmo_.axis(int(handle_)), forward) >= 0 ? -1 : 1;
        const double degrees = sign * turnedDegrees_;
        return turned(snap ? snapped(degrees, Gizmo::kSnapDegrees) : degrees);
    }
    if (handle_ == GizmoHandle::Screen) {
        const auto from = onScreenPlane(pressedAt_), to = onScreenPlane(point);
        return from && to ? moved(*to - *from, snap) : start;
    }
    const auto from = alongAxis(pressedAt_), to = alongAxis(point);
    if (!from || !to) return start;
    double distance = *to - *from;
    const int i = int(handle_);
    if (!gizmo_.localAxes()) {
        // Along a parent axis only that one number changes, exactly.
        Pose pose = start;
        float& value = pose.position[i];
        value = float(snap ? snapped(value + distance, Gizmo::kSnapUnits) : value + distance);
        return pose;
    }
    if (snap) distance = snapped(distance, Gizmo::kSnapUnits);
    return moved(gizmo_.axis(i) * float(distance), false);
}

Pose GizmoDrag::moved(Vec3 worldDelta, bool snap) const {
    Pose pose = gizmo_.frame().pose;
    // The key's position is read in the parent's axes.
    const Vec3 delta = gizmo_.frame().parent.linear.transposed() * worldDelta;
    const auto step = [&](float& value, float by) {
        value += by;
        if (snap) value = float(snapped(value, Gizmo::kSnapUnits));
    };
    step(pose.position.x, delta.x);
    step(pose.position.y, delta.y);
    step(pose.position.z, delta.z);
    return pose;
}

Pose GizmoDrag::turned(double degrees) const {
    Pose pose = gizmo_.frame().pose;
    const GizmoFrame& frame = gizmo_.frame();
    // world rotation = M · R(key), M = parent · rest: the turn about world axis u
    // makes R(key') = Mᵀ · Rot(u) · M · R(key).
    const Mat3 m = frame.parent.linear * frame.rest;
    const Vec3 u = gizmo_.axis(int(handle_));
    const Mat3 turn = rotationAbout(u, degrees);
    const int i = int(handle_);
    // Rz·Ry·Rx: a turn about the key's own z (parent axes) or about the target's own
    // x (local axes) adds to that one angle; written as such, it stays exact.
    if (!gizmo_.localAxes() && i == 2 && (m.transposed() * u).z > 1 - 1e-6f)
        pose.rotation.z += float(degrees);
    else if (gizmo_.localAxes() && i == 0)
        pose.rotation.x += float(degrees);
    else
        pose.rotation = eulerDegreesNear(m.transposed() * turn * m * rotationFromEulerDegrees(pose.rotation),
                                         pose.rotation);
    if (!(frame.handle == Vec3{})) {
        // About the handles' centre c, not the frame's origin o: o goes to c + turn·(o − c).
        const Vec3 c = frame.centre(), o = frame.world().translation;
        pose.position = frame.parent.linear.transposed() * (c + turn * (o - c) - frame.parent.translation);
    }
    return pose;
}

}  // namespace f2::viewer
