#include "io/bench_scenes.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

#include "core/math/transform.h"
#include "core/util/decimal_text.h"

namespace f2 {

namespace {

/// Shortest decimal form, independent of the C++ and C locales (SPEC 7 reads
/// numbers in the C locale).
std::string num(double v) {
    if (std::fabs(v) < 1e-9) v = 0;  // no "-0" or 1e-15 noise in the text
    return generalText(v, 9);
}

void append(std::string& out, std::initializer_list<std::string_view> parts) {
    for (std::string_view part : parts) out += part;
}

/// Appends " n1 n2 ..." (each number after a space).
void appendNumbers(std::string& out, std::initializer_list<double> values) {
    for (double v : values) {
        out += ' ';
        out += num(v);
    }
}

constexpr std::array<std::array<int, 3>, 4> kPalette = {
    {{220, 60, 60}, {60, 90, 220}, {230, 200, 40}, {200, 200, 200}}};

/// Phase of object i: neighbours move out of step, so the scene looks alive
/// and the BVH sees a different layout at each frame.
double phaseOf(int i) { return 0.7 * double(i); }

}  // namespace

namespace {
/// The kinds' words, in BenchShape order.
constexpr std::array<std::string_view, 5> kShapeWords = {"robots", "spheres", "drives", "drivekeys", "lamps"};
}  // namespace

bool parseBenchSceneSpec(std::string_view text, BenchSceneSpec& spec, std::string& error) {
    auto colon = text.find(':');
    std::string_view kind = text.substr(0, colon);
    BenchSceneSpec parsed;
    const auto word = std::find(kShapeWords.begin(), kShapeWords.end(), kind);
    if (colon == std::string_view::npos || word == kShapeWords.end()) {
        error.assign("expected robots:N, spheres:N or lamps:N (or drives:N, drivekeys:N), got '")
            .append(text)
            .append("'");
        return false;
    }
    parsed.shape = BenchShape(word - kShapeWords.begin());
    std::string_view count = text.substr(colon + 1);
    const char* end = count.data() + count.size();
    auto [ptr, ec] = std::from_chars(count.data(), end, parsed.count);
    const int most = benchMaxCount(parsed.shape);
    if (count.empty() || ec != std::errc{} || ptr != end || parsed.count < 1 || parsed.count > most) {
        error.assign("N in '")
            .append(text)
            .append("' must be a whole number 1..")
            .append(std::to_string(most));
        if (parsed.shape == BenchShape::Lamps)
            error.append(" (a light per lamp; at most 1000 lights, SPEC 7)");
        return false;
    }
    spec = parsed;
    return true;
}

int benchMaxCount(BenchShape shape) { return shape == BenchShape::Lamps ? kMaxBenchLamps : kMaxBenchObjects; }

std::string benchSceneName(const BenchSceneSpec& spec) {
    return std::string(kShapeWords[std::size_t(spec.shape)]).append(":").append(std::to_string(spec.count));
}

BenchGrid benchGrid(int count) {
    int columns = int(std::sqrt(double(count)));
    while (columns * columns < count) ++columns;  // exact ceil(sqrt(N)), no rounding surprises
    if (columns < 1) columns = 1;
    return {columns, (count + columns - 1) / columns};
}

BenchCamera benchCamera(int count) {
    // Look down at `pitch` toward the grid's centre C = (0, -5, 0) (mid-height
    // of a robot) from distance D = 100 + 2 * half, half = 75 * max(columns, rows)
    // the grid's half-width. With d = 0.5 (tangents 1 across, 0.75 up at 4:3)
    // the binding limits are the near corners sideways (D >= 1.87 half - 57)
    // and the near edge downward (D >= 1.63 half + 58), each with 5% margin.
    BenchGrid grid = benchGrid(count);
    double half = 0.5 * kBenchSpacing * double(std::max(grid.columns, grid.rows));
    double distance = 100.0 + 2.0 * half;
    double pitch = kBenchPitchDegrees * kPi / 180.0;
    // Eye = C - D * forward, forward = R(pitch, 0, 0) * (0, 0, 1) = (0, -sin, cos).
    return {0.0, -5.0 + distance * std::sin(pitch), -distance * std::cos(pitch), kBenchPitchDegrees};
}

namespace {

/// The lamp of docs/gallery.md's desk_lamps.f2 (base, arm, head), its shapes
/// glowing a little (`emit`): the scene has no ambient or directional light,
/// only the lamps' own.
constexpr std::string_view kLampModel =
    "/model lamp\n"
    "/part base root 0 0 0\n"
    "/part arm base 0 22 0 20 0 0\n"
    "/part head arm 0 120 0 -45 0 0\n"
    "/cylinder base.foot 34 8 0 4 0\n"
    "/cylinder base.post 6 14 0 13 0\n"
    "/sphere arm.knob 7 0 0 0\n"
    "/cylinder arm.rod 3.5 120 0 60 0\n"
    "/sphere head.joint 7 0 0 0\n"
    "/cylinder head.cap 9 14 0 -4 0\n"
    "/cylinder head.shade 22 24 0 -20 0\n"
    "/sphere head.bulb 9 0 -33 0\n"
    "/paint head.bulb 255 235 170\n"
    "/material head.bulb 0 0 0 1 emit 1\n"
    "/material base.foot 1 1 0.3 32 emit 0.15\n"
    "/material base.post 1 1 0.3 32 emit 0.15\n"
    "/material arm.knob 1 1 0.3 32 emit 0.15\n"
    "/material arm.rod 1 1 0.3 32 emit 0.15\n"
    "/material head.joint 1 1 0.3 32 emit 0.15\n"
    "/material head.cap 1 1 0.3 32 emit 0.15\n"
    "/material head.shade 1 1 0.3 32 emit 0.15\n"
    "/end\n";

/// Lamp i: its light (a point light just below the bulb, riding on the head)
/// and its keys: the base turns, the arm bows and the head nods, out of phase.
void appendLamp(std::string& out, int i, double x, double z) {
    const std::string lamp = "l" + std::to_string(i), light = "b" + std::to_string(i);
    const auto& color = kPalette[std::size_t(i) & 3];
    const double phase = phaseOf(i);
    append(out, {"/lamp ", lamp});
    appendNumbers(out, {x, -105, z, 0, 180, 0});
    append(out, {"\n/paint ", lamp});
    appendNumbers(out, {double(color[0]), double(color[1]), double(color[2])});
    append(out, {"\n/point_light 0.7 0 -46 0 fade 60 2 name ", light, "\n/attach ", light, " ", lamp,
                 ".head\n/interp ", lamp, ".arm spline\n/interp ", lamp, ".head ease\n/interp ", lamp,
                 ".base ease\n"});
    for (int k = 0; k <= 4; ++k) {
        const std::string frame = std::to_string(k * kBenchSwingFrames / 4);
        append(out, {"/key ", frame, " ", lamp, ".arm 0 0 0"});
        appendNumbers(out, {15.0 * std::sin(phase + k * kPi / 2), 0, 0});
        append(out, {"\n/key ", frame, " ", lamp, ".head 0 0 0"});
        appendNumbers(out, {-25.0 * std::cos(phase + k * kPi / 2), 0, 0});
        out += '\n';
    }
    for (int k = 0; k <= 2; ++k) {
        append(out, {"/key ", std::to_string(k * kBenchSwingFrames / 2), " ", lamp, ".base 0 0 0 0"});
        appendNumbers(out, {(k % 2 ? -30.0 : 30.0) * std::cos(phase), 0});
        out += '\n';
    }
}

}  // namespace

std::string benchSceneText(const BenchSceneSpec& spec, int width, int height) {
    const bool robots = spec.shape == BenchShape::Robots;
    const bool driven = spec.shape == BenchShape::Drives || spec.shape == BenchShape::DriveKeys;
    const bool lamps = spec.shape == BenchShape::Lamps;
    const BenchGrid grid = benchGrid(spec.count);
    const BenchCamera cam = benchCamera(spec.count);
    std::string out;
    out.reserve(std::size_t(spec.count) * (robots || lamps ? 640 : 220) + 2048);
    // Built by appending pieces: GCC 12 misreports `"literal" + std::string` (-Wrestrict).
    append(out,
           {"# f2 bench --scene ", benchSceneName(spec), ": ", std::to_string(grid.columns), " x ",
            std::to_string(grid.rows), " grid, spacing ", num(kBenchSpacing), " (docs/performance.md)\n"});
    append(out, {"/camera ", std::to_string(width), " ", std::to_string(height), " 0.5"});
    appendNumbers(out, {cam.eyeX, cam.eyeY, cam.eyeZ, cam.pitch, 0, 0});
    if (lamps)
        out += "\n/background 20 22 30\n";  // the lamps' lights only: 1,000 lamps are SPEC 7's 1,000 lights
    else
        out += "\n/background 115 153 217\n/amb_light 0.2\n/dir_light 0.75 0.5 -1 0.7\n";
    // Floor: top face at y = -105, where robots stand; one cell of margin around the grid.
    out += "/box floor";
    appendNumbers(out, {grid.columns * kBenchSpacing + 2 * kBenchSpacing, 50,
                        grid.rows * kBenchSpacing + 2 * kBenchSpacing, 0, -130, 0});
    out += lamps ? "\n/paint floor 150 140 120\n" : "\n/paint floor 0 200 0\n";
    if (lamps) out += kLampModel;
    // Drives add no keys: one key of the floor (where it stands) makes the animation 0..48 long.
    if (spec.shape == BenchShape::Drives)
        append(out, {"/key ", std::to_string(kBenchSwingFrames), " floor\n"});

    std::string name;
    for (int i = 0; i < spec.count; ++i) {
        const int column = i % grid.columns, row = i / grid.columns;
        const double x = (column - (grid.columns - 1) * 0.5) * kBenchSpacing;
        const double z = (row - (grid.rows - 1) * 0.5) * kBenchSpacing;
        if (lamps) {
            appendLamp(out, i, x, z);
            continue;
        }
        name.clear();
        name += robots ? 'r' : 's';
        name += std::to_string(i);
        const auto& color = kPalette[std::size_t(i) & 3];
        const double phase = phaseOf(i);
        if (robots) {
            // Facing the camera (ry 180); arms swing in opposition along a
            // spline and the head turns, each robot out of phase.
            append(out, {"/robot ", name});
            appendNumbers(out, {x, 0, z, 0, 180, 0});
            append(out, {"\n/paint ", name});
            appendNumbers(out, {double(color[0]), double(color[1]), double(color[2])});
            append(out, {"\n/interp ", name, ".lhand spline\n/interp ", name, ".rhand spline\n/interp ", name,
                         ".head ease\n"});
            for (int k = 0; k <= 4; ++k) {
                const std::string frame = std::to_string(k * kBenchSwingFrames / 4);
                const double swing = 40.0 * std::sin(phase + k * kPi / 2);
                append(out, {"/key ", frame, " ", name, ".lhand 0 0 0"});
                appendNumbers(out, {swing, 0, 0});
                append(out, {"\n/key ", frame, " ", name, ".rhand 0 0 0"});
                appendNumbers(out, {-swing, 0, 0});
                out += '\n';
            }
            for (int k = 0; k <= 2; ++k) {
                append(out, {"/key ", std::to_string(k * kBenchSwingFrames / 2), " ", name, ".head 0 0 0 0"});
                appendNumbers(out, {(k % 2 ? -30.0 : 30.0) * std::cos(phase), 0});
                out += '\n';
            }
        } else if (driven) {
            // Radius 50 swaying in x and bobbing in y, driven (two channels)
            // or keyed (two linear keys of the pose) over the same 48 frames.
            append(out, {"/sphere ", name, " 50"});
            appendNumbers(out, {x, -40, z});
            append(out, {"\n/paint ", name});
            appendNumbers(out, {double(color[0]), double(color[1]), double(color[2])});
            out += '\n';
            const double degrees = phase * 180 / kPi;
            if (spec.shape == BenchShape::Drives) {
                append(out,
                       {"/drive ", name, " px (", num(x), " + 20*sin(time*180 + ", num(degrees), "))\n"});
                append(out, {"/drive ", name, " py (-40 + 15*cos(frame*7.5 + ", num(degrees), "))\n"});
            } else {
                append(out, {"/key 0 ", name});
                appendNumbers(out, {x - 20, -55, z, 0, 0, 0});
                append(out, {"\n/key ", std::to_string(kBenchSwingFrames), " ", name});
                appendNumbers(out, {x + 20, -25, z, 0, 0, 0});
                out += '\n';
            }
        } else {
            // Radius 50 resting on the floor (centre y = -55), bobbing up to 30.
            const double low = -55 + 15 * (1 + std::sin(phase)), high = -55 + 15 * (1 - std::sin(phase));
            append(out, {"/sphere ", name, " 50"});
            appendNumbers(out, {x, low, z});
            append(out, {"\n/paint ", name});
            appendNumbers(out, {double(color[0]), double(color[1]), double(color[2])});
            append(out, {"\n/interp ", name, " ease\n"});
            for (int k = 0; k <= 2; ++k) {
                append(out, {"/key ", std::to_string(k * kBenchSwingFrames / 2), " ", name});
                appendNumbers(out, {x, k % 2 ? high : low, z, 0, 0, 0});
                out += '\n';
            }
        }
    }
    return out;
}

}  // namespace f2
