#pragma once
/// Triangle meshes of the exact primitives (SPEC 4), for formats that hold
/// only triangles (glTF). Every vertex lies on the exact surface and carries
/// the exact normal there, so a mesh differs from the primitive only between
/// its vertices.
#include <cstdint>
#include <vector>

#include "core/geometry/shape_kind.h"
#include "core/math/vec3.h"

namespace f2 {

/// Bounds of `segments`: a triangle is still a cylinder, beyond 1024 a mesh
/// costs more than it shows.
inline constexpr int kMinTessellation = 3;
inline constexpr int kMaxTessellation = 1024;

struct TriangleMesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  ///< unit, outward, one per position
    /// Three per triangle, counter-clockwise seen from outside when read in a
    /// right-handed frame (cross(b - a, c - a) points out).
    std::vector<std::uint32_t> indices;
};

/// The shape in its canonical frame (centred, cylinder axis y): a sphere of
/// radius size.x as `segments` slices by segments/2 (at least 2) stacks; a
/// closed cylinder (radius size.x, height size.y) as `segments` sides and two
/// capped fans; a box (sides size.x, size.y, size.z) as 6 faces of 2
/// triangles, whatever `segments`. No triangle is degenerate.
TriangleMesh tessellate(ShapeKind kind, Vec3 size, int segments);

}  // namespace f2
