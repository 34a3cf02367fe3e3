#pragma once
/// One evaluated frame as a POV-Ray 3.7 scene, so a frame can be handed to
/// POV-Ray (area lights, radiosity, anything it does) with the same view.
///
/// Exact: the camera (SPEC 2, as right/up/direction vectors; POV-Ray is
/// left-handed too), every primitive's transform (`matrix`), colours, the
/// background; checker patterns (`pigment { checker }` in the shape's frame)
/// and mirrors (`reflection`, f2's trace levels, no adaptive depth control);
/// colour arithmetic in display space (`assumed_gamma srgb`, which with
/// POV-Ray's default sRGB file gamma means no gamma conversion), as f2
/// shades. Approximate: POV-Ray's Phong and shadow details.
#include <string>

#include "core/render/camera.h"
#include "core/scene/scene_desc.h"

namespace f2 {

/// The scene at time `t` (frames) seen by `camera` (its size is the image
/// size POV-Ray should be run at: +W +H). `source` names the scene in a comment.
std::string povScene(const SceneDesc& scene, double t, const Camera& camera, const std::string& source);

}  // namespace f2
