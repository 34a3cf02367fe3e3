#pragma once
/// An RGB image of float colours (0..1, the shaded values before the 8-bit
/// conversion), rows top to bottom: where several images are averaged (motion
/// blur) so that rounding happens once, at the end.
#include "core/render/image.h"

namespace f2 {

struct LinearRgb {
    float r = 0, g = 0, b = 0;
    friend bool operator==(const LinearRgb&, const LinearRgb&) = default;
};

using LinearImage = PixelGrid<LinearRgb>;

}  // namespace f2
