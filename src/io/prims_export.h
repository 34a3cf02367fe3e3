#pragma once
/// One evaluated frame as the plain-text primitive list read by the Embree
/// peer renderer (bench/embree_peer; the format is in docs/output.md): camera,
/// background, lights, then every primitive in scene order with its 3x4
/// local-to-world matrix, colour and material.
#include <string>

#include "core/render/camera.h"
#include "core/scene/scene_desc.h"

namespace f2 {

std::string primsScene(const SceneDesc& scene, double t, const Camera& camera, const std::string& source);

}  // namespace f2
