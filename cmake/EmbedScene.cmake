# cmake -DINPUT=scene.f2 -DOUTPUT=file.cpp -P EmbedScene.cmake
# Writes defaultSceneText() returning the file's bytes as a raw string literal.
file(READ "${INPUT}" F2_TEXT)
string(FIND "${F2_TEXT}" ")F2SCENE\"" F2_CLASH)
if(NOT F2_CLASH EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw-string delimiter )F2SCENE\"")
endif()
file(WRITE "${OUTPUT}.tmp"
"// Generated from ${INPUT}; do not edit.\n#include \"core/scene/default_scene.h\"\n\nnamespace f2 {\nstd::string_view defaultSceneText() {\n    static constexpr char kText[] = R\"F2SCENE(${F2_TEXT})F2SCENE\";\n    return {kText, sizeof(kText) - 1};\n}\n}  // namespace f2\n")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
