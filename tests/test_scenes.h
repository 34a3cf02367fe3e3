#pragma once
/// Helpers shared by tests: parse a scene from text or from scenes/, fail loudly.
#include <string>
#include <string_view>

#include "core/scene/scene_desc.h"

namespace f2::test {

/// Parses `text`; the test fails (with every diagnostic) if it has an error.
SceneDesc sceneFromText(std::string_view text);
/// Parses scenes/<name> of the source tree.
SceneDesc sceneFromRepo(const std::string& name);
/// Absolute path of a file in the source tree.
std::string sourcePath(const std::string& relative);

}  // namespace f2::test
