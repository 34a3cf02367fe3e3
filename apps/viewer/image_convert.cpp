#include "image_convert.h"

#include <cstring>

namespace f2::viewer {

// Rows are copied as packed RGB triples; this relies on Rgb8 having no padding.
static_assert(sizeof(Rgb8) == 3, "Rgb8 must be three packed bytes");

QImage toQImage(const Image& image) {
    if (image.width <= 0 || image.height <= 0) return {};
    const auto* data = reinterpret_cast<const uchar*>(image.pixels.data());
    // copy(): the wrapper borrows `image`'s buffer, which the renderer reuses.
    return QImage(data, image.width, image.height, 3 * image.width, QImage::Format_RGB888).copy();
}

Image fromQImage(const QImage& source) {
    Image out;
    if (source.isNull()) return out;
    const QImage rgb = source.convertToFormat(QImage::Format_RGB888);
    out.resize(rgb.width(), rgb.height());
    const std::size_t rowBytes = std::size_t(rgb.width()) * 3;
    for (int y = 0; y < rgb.height(); ++y)
        std::memcpy(&out.at(0, y), rgb.constScanLine(y), rowBytes);  // scanlines may be padded
    return out;
}

}  // namespace f2::viewer
