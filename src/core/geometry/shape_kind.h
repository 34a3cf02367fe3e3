#pragma once
/// The three shapes the tracer intersects exactly. Geometry owns the list;
/// the scene's models name their parts' shapes with it.
#include <cstdint>
#include <string_view>

namespace f2 {

enum class ShapeKind : std::uint8_t { Sphere, Cylinder, Box };

/// "sphere", "cylinder" or "box", as the scene language and the exports write it.
constexpr std::string_view shapeKindName(ShapeKind kind) {
    switch (kind) {
        case ShapeKind::Sphere:
            return "sphere";
        case ShapeKind::Cylinder:
            return "cylinder";
        case ShapeKind::Box:
            return "box";
    }
    return "?";
}

}  // namespace f2
