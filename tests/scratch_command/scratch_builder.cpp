// The scratch command's one builder function (SceneBuilder::dispatch calls it
// in this build): a sphere, read with the argument counts of its row.
#include "core/parse/scene_builder.h"

namespace f2::parsing {

void SceneBuilder::parseScratch() { parseObject(ObjectKind::Sphere); }

}  // namespace f2::parsing
