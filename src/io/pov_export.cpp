#include "io/pov_export.h"

#include <sstream>

#include "io/comment_text.h"
#include "io/pov_scene_text.h"

namespace f2 {

std::string povScene(const SceneDesc& scene, double t, const Camera& camera, const std::string& source) {
    const std::vector<PlacedPrimitive> prims = framePrimitives(scene, t);
    PovBounds bounds;
    bounds.grow(camera, prims);
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out << "// " << commentText(source) << " at frame " << t << ", exported by f2 (F2 Stage).\n"
        << "// Render: povray +I<this file> +O<image>.png +W" << camera.width << " +H" << camera.height
        << " -A +FN -D\n"
        << "// (+A0.1 for anti-aliasing). Coordinates are f2's: left-handed, y up, like POV-Ray's.\n"
        << "#version 3.7;\n\n"
        << povSceneBody(scene, prims, povValuesAt(scene, t, camera, prims, bounds));
    return out.str();
}

}  // namespace f2
