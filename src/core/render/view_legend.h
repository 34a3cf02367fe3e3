#pragma once
/// The legend of the scaled diagnostic views (depth, cost), drawn into the
/// image so that every output (a PNG, a video frame, the viewer) can be read:
/// a bar of the view's colour ramp with the value of each end under it.
#include "core/render/diagnostic_view.h"
#include "core/render/image.h"

namespace f2 {

/// Space the legend takes, in pixels, at the image's bottom-left corner.
inline constexpr int kLegendWidth = 136, kLegendHeight = 29, kLegendMargin = 4;

/// Draws the legend of `mode` over `range` into `image`: for depth the grey
/// ramp from the nearest distance to the farthest, for cost the heat ramp from
/// 0 to the largest cost. Nothing for the other modes, or when the image is
/// smaller than the legend and its margins. Returns whether it drew.
bool drawViewLegend(Image& image, ViewMode mode, const ViewRange& range);

}  // namespace f2
