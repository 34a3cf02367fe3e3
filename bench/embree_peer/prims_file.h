#pragma once
/// The primitive list that `f2 export --prims` writes (docs/output.md): one
/// evaluated frame as camera, background, lights and world-space primitives.
/// The Embree peer reads only this, never a scene file, so it renders exactly
/// the frame f2 evaluated.
#include <cstdint>
#include <string>
#include <vector>

namespace f2::peer {

/// A 3x4 affine map [A | t], rows: world = A * local + t.
struct Affine {
    float m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    float linear(int row, int col) const { return m[row][col]; }
    float translation(int row) const { return m[row][3]; }
};

enum class ShapeKind : std::uint32_t { Sphere, Cylinder, Box };

/// One `sphere|cylinder|box` line.
struct PrimRecord {
    ShapeKind kind = ShapeKind::Sphere;
    float radius = 0, height = 0;  ///< sphere: radius; cylinder: radius and height
    float sides[3] = {0, 0, 0};    ///< box: side lengths along local x, y, z
    Affine worldFromLocal;         ///< canonical frame: centred, cylinder axis along local y
    std::uint8_t rgb[3] = {200, 200, 200};
    float ka = 1, kd = 1, ks = 0.3f, shininess = 32;
};

/// One `dir` line: the direction the light travels, as written in the scene.
struct DirLight {
    float intensity = 0;
    float direction[3] = {0, 0, 0};
};

/// A whole file.
struct PrimsFrame {
    int width = 0, height = 0;
    float distance = 0.5f;   ///< eye-to-screen distance in screen widths (SPEC 2)
    Affine worldFromCamera;  ///< columns: right, up, forward; translation: the eye
    std::uint8_t background[3] = {0, 0, 0};
    float ambient = 0;  ///< sum of the `amb` lines
    std::vector<DirLight> lights;
    std::vector<PrimRecord> prims;  ///< in scene order: the index breaks ties
};

/// Reads `path`. On failure returns false and sets `error` to
/// "FILE:LINE:COL: error: what" (the first problem).
bool readPrimsFile(const std::string& path, PrimsFrame& frame, std::string& error);

/// The same from text already in memory; `name` stands for the file in errors.
bool parsePrims(const std::string& text, const std::string& name, PrimsFrame& frame, std::string& error);

}  // namespace f2::peer
