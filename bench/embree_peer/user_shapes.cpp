#include "user_shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace f2::peer {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

/// Where a ray is inside a shape: t from `enter` to `exit`, and the faces.
/// Written without branches on the ray, so a loop over packet lanes vectorises.
struct Span {
    float enter = -kInf, exit = kInf;
    int enterFace = kSlabX, exitFace = kSlabX;
    bool ok = true;
};

/// Narrows `span` to the slab |o + t d| <= h along one local axis. Shapes are
/// intersections of slabs (and of an infinite cylinder): entry is the last
/// entry, exit the first exit, so no ray slips through an edge or a cap rim.
inline void clipSlab(float o, float d, float h, int face, Span& span) {
    const bool along = d == 0.0f;  // never crosses the planes
    const float inv = 1.0f / d;
    const float t0 = (-h - o) * inv, t1 = (h - o) * inv;
    const bool swapped = t0 > t1;
    const float lo = swapped ? t1 : t0, hi = swapped ? t0 : t1;
    const bool later = !along & (lo > span.enter), sooner = !along & (hi < span.exit);
    span.enter = later ? lo : span.enter;
    span.enterFace = later ? face : span.enterFace;
    span.exit = sooner ? hi : span.exit;
    span.exitFace = sooner ? face : span.exitFace;
    span.ok = span.ok & ((along & (std::fabs(o) <= h)) | (!along & (span.enter <= span.exit)));
}

inline float dot3(float ax, float ay, float az, const float b[3]) {
    return ax * b[0] + ay * b[1] + az * b[2];
}

template <ShapeKind K>
inline Span shapeSpan(const Shape& s, float ox, float oy, float oz, float dx, float dy, float dz) {
    const float cx = ox - s.centre[0], cy = oy - s.centre[1], cz = oz - s.centre[2];
    Span span;
    if constexpr (K == ShapeKind::Sphere) {
        // Unit directions: the quadratic's a is 1. The discriminant from the
        // closest approach keeps precision for rays that start far away.
        const float r = s.half[0];
        const float b = cx * dx + cy * dy + cz * dz;
        const float qx = cx - dx * b, qy = cy - dy * b, qz = cz - dz * b;
        const float disc = r * r - (qx * qx + qy * qy + qz * qz);
        span.ok = disc >= 0;
        const float root = std::sqrt(std::max(disc, 0.0f));
        span.enter = -b - root;
        span.exit = -b + root;
        span.enterFace = span.exitFace = kCurved;
    } else if constexpr (K == ShapeKind::Cylinder) {
        const float* a = s.axes[1];
        const float r = s.half[0];
        const float oa = dot3(cx, cy, cz, a), da = dot3(dx, dy, dz, a);
        const float px = cx - a[0] * oa, py = cy - a[1] * oa, pz = cz - a[2] * oa;  // across the axis
        const float ex = dx - a[0] * da, ey = dy - a[1] * da, ez = dz - a[2] * da;  // its direction
        const float qa = ex * ex + ey * ey + ez * ez;
        const float c = (px * px + py * py + pz * pz) - r * r;
        const bool parallel = qa <= 1e-20f;  // inside for all t, or never
        const float invA = 1.0f / qa;
        const float b = px * ex + py * ey + pz * ez;
        const float kx = px - ex * (b * invA), ky = py - ey * (b * invA), kz = pz - ez * (b * invA);
        const float disc = r * r - (kx * kx + ky * ky + kz * kz);
        const float root = std::sqrt(disc >= 0 ? disc * qa : 0.0f);
        span.ok = (parallel & (c <= 0)) | (!parallel & (disc >= 0));
        span.enter = parallel ? -kInf : (-b - root) * invA;
        span.exit = parallel ? kInf : (-b + root) * invA;
        span.enterFace = span.exitFace = kCurved;
        clipSlab(oa, da, s.half[1], kCap, span);
    } else {
        for (int i = 0; i < 3; ++i)
            clipSlab(dot3(cx, cy, cz, s.axes[i]), dot3(dx, dy, dz, s.axes[i]), s.half[i], kSlabX + i, span);
    }
    return span;
}

/// The nearest surface crossing after tMin: the entry, or the exit when the
/// origin is inside.
inline bool nearestCrossing(const Span& span, float tMin, float& t, int& face) {
    const bool front = span.enter > tMin;
    t = front ? span.enter : span.exit;
    face = front ? span.enterFace : span.exitFace;
    return span.ok & (t > tMin);
}

// Offsets into Embree's SOA packet of N rays (RTCRayHitNt<N>), in floats.
enum : unsigned { kOrgX = 0, kOrgY, kOrgZ, kTNear, kDirX, kDirY, kDirZ, kTime, kTFar, kMask, kId, kFlags };
enum : unsigned { kNgX = 12, kNgY, kNgZ, kU, kV, kPrimId, kGeomId, kInstId };

/// nearestCrossing() of lane `i` of an SOA packet of N rays.
template <unsigned N, ShapeKind K>
inline bool laneCrossing(const Shape& s, const float* rays, unsigned i, float& t, int& face) {
    const Span span = shapeSpan<K>(s, rays[kOrgX * N + i], rays[kOrgY * N + i], rays[kOrgZ * N + i],
                                   rays[kDirX * N + i], rays[kDirY * N + i], rays[kDirZ * N + i]);
    return nearestCrossing(span, rays[kTNear * N + i], t, face);
}

/// Closest hit of one shape for the valid lanes. At an equal distance the
/// primitive earlier in scene order wins, so the image does not depend on the
/// order in which the BVH offers primitives. A lane starts with primID
/// RTC_INVALID_GEOMETRY_ID, the largest, and tfar the farthest distance.
template <unsigned N, ShapeKind K>
void intersectLanes(const int* valid, const Shape& s, unsigned primId, unsigned geomId, unsigned instId,
                    float* packet) {
    float* tfar = packet + kTFar * N;
    float* face = packet + kU * N;
    unsigned* prims = reinterpret_cast<unsigned*>(packet + kPrimId * N);
    unsigned* geoms = reinterpret_cast<unsigned*>(packet + kGeomId * N);
    unsigned* insts = reinterpret_cast<unsigned*>(packet + kInstId * N);
#pragma omp simd
    for (unsigned i = 0; i < N; ++i) {
        float t;
        int f;
        const bool hit = laneCrossing<N, K>(s, packet, i, t, f);
        // Bitwise, not short-circuit: no branches in the lane loop.
        const float current = tfar[i];
        const bool nearer = (t < current) | ((t == current) & (primId < prims[i]));
        // Blends, stored back unchanged where not taken: no branches, so the
        // loop vectorises.
        const bool take = (valid[i] != 0) & hit & nearer;
        tfar[i] = take ? t : current;
        face[i] = take ? float(f) : face[i];
        prims[i] = take ? primId : prims[i];
        geoms[i] = take ? geomId : geoms[i];
        insts[i] = take ? instId : insts[i];
    }
}

/// Any hit of one shape for the valid lanes; an occluded lane's tfar becomes -inf.
template <unsigned N, ShapeKind K>
void occludedLanes(const int* valid, const Shape& s, unsigned primId, float* ray) {
    float* tfar = ray + kTFar * N;
    const unsigned* skip = reinterpret_cast<const unsigned*>(ray + kId * N);
#pragma omp simd
    for (unsigned i = 0; i < N; ++i) {
        float t;
        int f;
        const bool hit = laneCrossing<N, K>(s, ray, i, t, f);
        const float current = tfar[i];
        tfar[i] = (valid[i] != 0) & hit & (t < current) & (skip[i] != primId) ? -kInf : current;
    }
}

/// Calls `kernel` with Embree's query width as a constant (1 for single
/// rays, 4, 8 or 16 for packets) and the shape kind as a constant, so that
/// the lane loops are compiled for each and vectorise.
template <class Kernel>
void withWidthAndKind(unsigned width, ShapeKind kind, Kernel kernel) {
    auto withKind = [&](auto n) {
        switch (kind) {
            case ShapeKind::Sphere:
                return kernel(n, std::integral_constant<ShapeKind, ShapeKind::Sphere>{});
            case ShapeKind::Cylinder:
                return kernel(n, std::integral_constant<ShapeKind, ShapeKind::Cylinder>{});
            case ShapeKind::Box:
                return kernel(n, std::integral_constant<ShapeKind, ShapeKind::Box>{});
        }
    };
    switch (width) {
        case 1:
            return withKind(std::integral_constant<unsigned, 1>{});
        case 4:
            return withKind(std::integral_constant<unsigned, 4>{});
        case 8:
            return withKind(std::integral_constant<unsigned, 8>{});
        case 16:
            return withKind(std::integral_constant<unsigned, 16>{});
    }
}

void intersectCallback(const RTCIntersectFunctionNArguments* args) {
    const Shape& s = static_cast<const Shape*>(args->geometryUserPtr)[args->primID];
    withWidthAndKind(args->N, s.kind, [&](auto n, auto kind) {
        intersectLanes<n(), kind()>(args->valid, s, args->primID, args->geomID, args->context->instID[0],
                                    reinterpret_cast<float*>(args->rayhit));
    });
}

void occludedCallback(const RTCOccludedFunctionNArguments* args) {
    const Shape& s = static_cast<const Shape*>(args->geometryUserPtr)[args->primID];
    withWidthAndKind(args->N, s.kind, [&](auto n, auto kind) {
        occludedLanes<n(), kind()>(args->valid, s, args->primID, reinterpret_cast<float*>(args->ray));
    });
}

void boundsCallback(const RTCBoundsFunctionArguments* args) {
    const Shape& s = static_cast<const Shape*>(args->geometryUserPtr)[args->primID];
    float extent[3];
    for (int i = 0; i < 3; ++i) {
        switch (s.kind) {
            case ShapeKind::Sphere:
                extent[i] = s.half[0];
                break;
            case ShapeKind::Cylinder: {
                // The cap disc of radius r across axis a reaches r*sqrt(1 - a_i^2) along world axis i.
                const float a = s.axes[1][i];
                extent[i] = std::fabs(a) * s.half[1] + s.half[0] * std::sqrt(std::max(0.0f, 1.0f - a * a));
                break;
            }
            case ShapeKind::Box:
                extent[i] = std::fabs(s.axes[0][i]) * s.half[0] + std::fabs(s.axes[1][i]) * s.half[1] +
                            std::fabs(s.axes[2][i]) * s.half[2];
                break;
        }
    }
    // Padding against rounding: a box must never clip its own surface, also
    // for a small shape far from the origin where floats are coarse.
    const float far = std::max({std::fabs(s.centre[0]), std::fabs(s.centre[1]), std::fabs(s.centre[2])});
    const float pad = 1e-6f * (1.0f + far);
    RTCBounds* b = args->bounds_o;
    b->lower_x = s.centre[0] - (extent[0] * 1.0001f + pad);
    b->lower_y = s.centre[1] - (extent[1] * 1.0001f + pad);
    b->lower_z = s.centre[2] - (extent[2] * 1.0001f + pad);
    b->upper_x = s.centre[0] + (extent[0] * 1.0001f + pad);
    b->upper_y = s.centre[1] + (extent[1] * 1.0001f + pad);
    b->upper_z = s.centre[2] + (extent[2] * 1.0001f + pad);
}

RTCBuildQuality sceneQuality(BuildMode mode) {
    switch (mode) {
        case BuildMode::Low:
        case BuildMode::Refit:
            return RTC_BUILD_QUALITY_LOW;
        case BuildMode::Medium:
            return RTC_BUILD_QUALITY_MEDIUM;
        case BuildMode::Static:
        case BuildMode::High:
            return RTC_BUILD_QUALITY_HIGH;
    }
    return RTC_BUILD_QUALITY_MEDIUM;
}

}  // namespace

Shape makeShape(const PrimRecord& record) {
    Shape s{};
    s.kind = record.kind;
    for (int row = 0; row < 3; ++row) {
        s.centre[row] = record.worldFromLocal.translation(row);
        for (int col = 0; col < 3; ++col) s.axes[col][row] = record.worldFromLocal.linear(row, col);
    }
    switch (record.kind) {
        case ShapeKind::Sphere:
            s.half[0] = s.half[1] = s.half[2] = record.radius;
            break;
        case ShapeKind::Cylinder:
            s.half[0] = s.half[2] = record.radius;
            s.half[1] = record.height * 0.5f;
            break;
        case ShapeKind::Box:
            for (int i = 0; i < 3; ++i) s.half[i] = record.sides[i] * 0.5f;
            break;
    }
    return s;
}

UserShapeScene::UserShapeScene(RTCDevice device, BuildMode mode) {
    scene_ = rtcNewScene(device);
    rtcSetSceneFlags(scene_, mode == BuildMode::Static ? RTC_SCENE_FLAG_NONE : RTC_SCENE_FLAG_DYNAMIC);
    rtcSetSceneBuildQuality(scene_, sceneQuality(mode));
    geometry_ = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryBuildQuality(geometry_,
                               mode == BuildMode::Refit ? RTC_BUILD_QUALITY_REFIT : sceneQuality(mode));
    rtcSetGeometryBoundsFunction(geometry_, boundsCallback, nullptr);
    rtcSetGeometryIntersectFunction(geometry_, intersectCallback);
    rtcSetGeometryOccludedFunction(geometry_, occludedCallback);
    rtcAttachGeometry(scene_, geometry_);
}

UserShapeScene::~UserShapeScene() {
    rtcReleaseGeometry(geometry_);
    rtcReleaseScene(scene_);
}

void UserShapeScene::setPrimitives(const std::vector<PrimRecord>& prims) {
    const bool resized = prims.size() != shapes_.size();
    shapes_.resize(prims.size());
    for (std::size_t i = 0; i < prims.size(); ++i) shapes_[i] = makeShape(prims[i]);
    if (resized) rtcSetGeometryUserPrimitiveCount(geometry_, unsigned(shapes_.size()));
    rtcSetGeometryUserData(geometry_, shapes_.data());
}

void UserShapeScene::commit() {
    rtcCommitGeometry(geometry_);  // marks the geometry changed: the scene rebuilds or refits it
    rtcCommitScene(scene_);
}

}  // namespace f2::peer
