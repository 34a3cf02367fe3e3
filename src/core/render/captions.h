#pragma once
/// Captions (SPEC 10.5): text drawn over the traced picture, in file order,
/// anti-aliased by stb_truetype from the font compiled into the core
/// (caption_font.h). One thread, integer blending: the same bytes on every
/// machine, build and thread count.
#include <span>

#include "core/render/image.h"
#include "core/scene/scene_desc.h"

namespace f2 {

/// Draws the captions shown at time `t` (frames; `from <= t < to`) into
/// `image`. Positions and sizes are fractions of the image, so a preview at a
/// quarter of the size shows the same captions at a quarter of the size.
void drawCaptions(Image& image, std::span<const Caption> captions, double t);

/// Draws one caption whatever its times.
void drawCaption(Image& image, const Caption& caption);

}  // namespace f2
