#pragma once
/// What a pixel shows: the shaded image (SPEC 3) or one of the diagnostic
/// views that show how the tracer sees the scene. Each mode's pixel formula is
/// in docs/rendering.md, "View modes".
#include <array>
#include <optional>
#include <string_view>

namespace f2 {

enum class ViewMode {
    Shaded,        ///< the image (SPEC 3), by the packet path
    Normals,       ///< (n + 1) / 2 of the normal turned to the viewer
    Depth,         ///< hit distance, near white to far dark (in 1/d), over this frame's range
    ShadowMask,    ///< per light: reaches (white), blocked (red), turned away (black)
    PrimitiveIds,  ///< a fixed colour per primitive index in scene order
    Cost,          ///< BVH node boxes + primitives tested, primary and shadow rays, as a heat map
};

/// Every mode, in menu order.
inline constexpr std::array<ViewMode, 6> kViewModes = {ViewMode::Shaded,       ViewMode::Normals,
                                                       ViewMode::Depth,        ViewMode::ShadowMask,
                                                       ViewMode::PrimitiveIds, ViewMode::Cost};

/// The name `f2 render --view` takes: "shaded", "normals", "depth", "shadow-mask",
/// "primitive-ids", "cost".
constexpr std::string_view viewModeName(ViewMode mode) {
    switch (mode) {
        case ViewMode::Shaded:
            return "shaded";
        case ViewMode::Normals:
            return "normals";
        case ViewMode::Depth:
            return "depth";
        case ViewMode::ShadowMask:
            return "shadow-mask";
        case ViewMode::PrimitiveIds:
            return "primitive-ids";
        case ViewMode::Cost:
            return "cost";
    }
    return "shaded";
}

/// The mode named `name` (viewModeName), or nothing.
constexpr std::optional<ViewMode> viewModeNamed(std::string_view name) {
    for (ViewMode mode : kViewModes)
        if (viewModeName(mode) == name) return mode;
    return std::nullopt;
}

}  // namespace f2
