#pragma once
/// Generated benchmark scenes `robots:N`, `spheres:N` and `lamps:N`
/// (docs/performance.md): N animated robots, N spheres or N desk lamps (a
/// model of three parts, SPEC 10.1, each with a named point light riding on
/// its head, 10.2) on a square grid over a floor, seen from a raised camera
/// that fits the whole grid; `drives:N`, N spheres each driven on two
/// channels (SPEC 10.7), and its twin `drivekeys:N`, the same spheres with
/// two linear keys instead, to compare the cost of drives with keys'. They
/// are produced as scene-language text, so the benchmark, `f2 export` and
/// other renderers all read the same scene through the one parser.
#include <string>
#include <string_view>

namespace f2 {

enum class BenchShape { Robots, Spheres, Drives, DriveKeys, Lamps };

struct BenchSceneSpec {
    BenchShape shape = BenchShape::Robots;
    int count = 1;  ///< N objects, 1..kMaxBenchObjects
};

/// Keeps a generated scene inside the parser's 1,000,000-object limit.
inline constexpr int kMaxBenchObjects = 1'000'000;
/// lamps:N has one light per lamp and no other: SPEC 7's 1,000 lights.
inline constexpr int kMaxBenchLamps = 1'000;
/// Distance between neighbouring grid cells (centimetres).
inline constexpr double kBenchSpacing = 150.0;
/// Camera pitch: rx of the camera, looking down at the grid (degrees).
inline constexpr double kBenchPitchDegrees = 35.0;
/// Frames of one full arm swing of the generated robots (keys every quarter).
inline constexpr int kBenchSwingFrames = 48;

/// Parses "robots:N", "spheres:N", "lamps:N", "drives:N" or "drivekeys:N";
/// false with a message on anything else.
bool parseBenchSceneSpec(std::string_view text, BenchSceneSpec& spec, std::string& error);

/// "robots:N", "spheres:N", "lamps:N", "drives:N" or "drivekeys:N".
std::string benchSceneName(const BenchSceneSpec& spec);

/// Grid of ceil(sqrt(N)) columns and ceil(N / columns) rows.
struct BenchGrid {
    int columns = 1, rows = 1;
};
BenchGrid benchGrid(int count);

/// Eye and pitch of a generated scene's camera (d = 0.5, no yaw or roll):
/// half = 75 * max(columns, rows), D = 100 + 2 * half,
/// eye = (0, -5 + D sin 35deg, -D cos 35deg), rotation (35, 0, 0).
/// Fits the grid in a 4:3 image (docs/performance.md).
struct BenchCamera {
    double eyeX = 0, eyeY = 0, eyeZ = 0, pitch = kBenchPitchDegrees;
};
BenchCamera benchCamera(int count);

/// The largest N of a shape: kMaxBenchLamps for lamps, else kMaxBenchObjects.
int benchMaxCount(BenchShape shape);

/// The whole scene in the scene language (SPEC 2-7) with `/camera width height`.
std::string benchSceneText(const BenchSceneSpec& spec, int width = 800, int height = 600);

}  // namespace f2
