#pragma once
/// The three shapes the tracer intersects exactly. Geometry owns the list;
/// the scene's models name their parts' shapes with it.
#include <cstdint>

namespace f2 {

enum class ShapeKind : std::uint8_t { Sphere, Cylinder, Box };

}  // namespace f2
