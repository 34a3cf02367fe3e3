#pragma once
/// The default scene (scenes/demo.f2), compiled into the binary.
#include <string_view>

namespace f2 {

std::string_view defaultSceneText();
/// Name used for the embedded scene in diagnostics and titles.
inline constexpr std::string_view kDefaultSceneName = "<default:demo.f2>";

}  // namespace f2
