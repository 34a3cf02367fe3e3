#include "io/tessellate.h"

#include <cmath>

#include "core/math/transform.h"

namespace f2 {

namespace {
std::uint32_t addVertex(TriangleMesh& mesh, Vec3 position, Vec3 normal) {
    mesh.positions.push_back(position);
    mesh.normals.push_back(normal);
    return std::uint32_t(mesh.positions.size() - 1);
}

void addTriangle(TriangleMesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

/// Point on the unit circle in the x-z plane at slice i of n. Seen from +y,
/// increasing i turns from +x toward -z: counter-clockwise in a right-handed frame.
Vec3 around(int i, int n) {
    const double a = 2.0 * kPi * double(i % n) / double(n);
    return {float(std::cos(a)), 0.0f, float(-std::sin(a))};
}

void sphere(TriangleMesh& mesh, float r, int slices) {
    const int stacks = std::max(2, slices / 2);
    // Rows from the north pole (y = r) to the south pole; a row's first and
    // last vertex coincide (the seam), the poles are rows of slices + 1 copies.
    for (int j = 0; j <= stacks; ++j) {
        const double polar = kPi * double(j) / double(stacks);
        const float y = j == 0 ? 1.0f : j == stacks ? -1.0f : float(std::cos(polar));
        const float ring = (j == 0 || j == stacks) ? 0.0f : float(std::sin(polar));
        for (int i = 0; i <= slices; ++i) {
            const Vec3 d = around(i, slices);
            const Vec3 n{d.x * ring, y, d.z * ring};
            addVertex(mesh, n * r, n);
        }
    }
    const auto at = [slices](int j, int i) { return std::uint32_t(j * (slices + 1) + i); };
    for (int j = 0; j < stacks; ++j) {
        for (int i = 0; i < slices; ++i) {
            // Quad (j, i) (j, i+1) (j+1, i) (j+1, i+1): its pole side is one point.
            if (j > 0) addTriangle(mesh, at(j, i), at(j + 1, i), at(j, i + 1));
            if (j + 1 < stacks) addTriangle(mesh, at(j, i + 1), at(j + 1, i), at(j + 1, i + 1));
        }
    }
}

void cylinder(TriangleMesh& mesh, float r, float h, int sides) {
    const float top = h / 2, bottom = -h / 2;
    const std::uint32_t side = std::uint32_t(mesh.positions.size());
    for (int i = 0; i <= sides; ++i) {
        const Vec3 d = around(i, sides);
        addVertex(mesh, {d.x * r, top, d.z * r}, d);
        addVertex(mesh, {d.x * r, bottom, d.z * r}, d);
    }
    for (int i = 0; i < sides; ++i) {
        const std::uint32_t t0 = side + 2 * std::uint32_t(i), b0 = t0 + 1, t1 = t0 + 2, b1 = t0 + 3;
        addTriangle(mesh, t0, b0, t1);
        addTriangle(mesh, t1, b0, b1);
    }
    // Caps: their own vertices, for the flat normal.
    for (const float y : {top, bottom}) {
        const Vec3 normal{0, y > 0 ? 1.0f : -1.0f, 0};
        const std::uint32_t centre = addVertex(mesh, {0, y, 0}, normal);
        for (int i = 0; i <= sides; ++i) {
            const Vec3 d = around(i, sides);
            addVertex(mesh, {d.x * r, y, d.z * r}, normal);
        }
        for (std::uint32_t i = 0; i < std::uint32_t(sides); ++i) {
            if (y > 0)
                addTriangle(mesh, centre, centre + 1 + i, centre + 2 + i);
            else
                addTriangle(mesh, centre, centre + 2 + i, centre + 1 + i);
        }
    }
}

void box(TriangleMesh& mesh, Vec3 size) {
    const Vec3 half = size * 0.5f;
    for (int axis = 0; axis < 3; ++axis) {
        for (const float sign : {1.0f, -1.0f}) {
            // u, v span the face with u x v = the outward normal.
            Vec3 normal, u, v;
            normal[axis] = sign;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = sign;
            const Vec3 centre{normal.x * half.x, normal.y * half.y, normal.z * half.z};
            const auto corner = [&](float a, float b) { return centre + u * a + v * b; };
            const float hu = half[(axis + 1) % 3], hv = half[(axis + 2) % 3];
            const std::uint32_t first = addVertex(mesh, corner(-hu, -hv), normal);
            addVertex(mesh, corner(hu, -hv), normal);
            addVertex(mesh, corner(hu, hv), normal);
            addVertex(mesh, corner(-hu, hv), normal);
            addTriangle(mesh, first, first + 1, first + 2);
            addTriangle(mesh, first, first + 2, first + 3);
        }
    }
}
}  // namespace

TriangleMesh tessellate(ShapeKind kind, Vec3 size, int segments) {
    TriangleMesh mesh;
    switch (kind) {
        case ShapeKind::Sphere:
            sphere(mesh, size.x, segments);
            break;
        case ShapeKind::Cylinder:
            cylinder(mesh, size.x, size.y, segments);
            break;
        case ShapeKind::Box:
            box(mesh, size);
            break;
    }
    return mesh;
}

}  // namespace f2
