#pragma once
/// Conversions between the core's RGB8 image and QImage.
#include <QImage>

#include "core/render/image.h"

namespace f2::viewer {

/// A deep copy as QImage::Format_RGB888 (the QImage owns its pixels).
QImage toQImage(const Image& image);
/// Any QImage as the core's RGB8 image (alpha dropped).
Image fromQImage(const QImage& image);

}  // namespace f2::viewer
