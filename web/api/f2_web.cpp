// The WebAssembly module's C API (docs/web.md): a page's worker sets the scene
// text, reads its diagnostics as JSON, and renders bands of rows of a frame as
// RGBA bytes. One scene and one renderer per module instance; one thread.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/parse/parser.h"
#include "core/render/camera.h"
#include "core/render/captions.h"
#include "core/render/orbit_camera.h"
#include "core/render/renderer.h"
#include "core/scene/default_scene.h"
#include "core/scene/drive.h"

namespace {

constexpr std::string_view kSceneName = "scene.f2";

struct Module {
    std::optional<f2::SceneDesc> scene;  ///< the last scene without errors
    /// The frame time the renderer last evaluated and built for this scene:
    /// the page renders a frame in many pieces (bands, previews, anti-aliasing).
    std::optional<double> preparedFrame;
    f2::Renderer renderer{1};  ///< no threads: the page runs one module per worker
    f2::Image image;
    std::vector<std::uint8_t> rgba;
    std::string text;  ///< returned strings live here until the next call
};

Module& module() {
    static Module m;
    return m;
}

void appendJsonString(std::string& out, std::string_view s) {
    out += '"';
    for (char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", unsigned(c));
            out += escaped;
        } else {
            out += c;
        }
    }
    out += '"';
}

/// Line `line` (1-based) of `text`, without its line end.
std::string_view lineOf(std::string_view text, int line) {
    std::size_t start = 0;
    for (int i = 1; i < line && start != std::string_view::npos; ++i) {
        start = text.find('\n', start);
        if (start != std::string_view::npos) ++start;
    }
    if (start == std::string_view::npos || start > text.size()) return {};
    std::string_view rest = text.substr(start);
    rest = rest.substr(0, rest.find('\n'));
    if (!rest.empty() && rest.back() == '\r') rest.remove_suffix(1);
    return rest;
}

/// What `f2 check` reports after parsing: the first frame at which a
/// `/drive` has no finite value, as a diagnostic ("FILE:LINE:COL: error: …").
std::optional<f2::Diagnostic> driveProblem(const f2::SceneDesc& scene) {
    for (int frame = 0; !scene.drives.empty() && frame <= scene.lastFrame(); ++frame) {
        const std::optional<std::string> problem = f2::firstDriveProblem(scene, double(frame));
        if (!problem) continue;
        const std::size_t error = problem->find(": error: ");
        const std::size_t colon2 = problem->rfind(':', error - 1);
        const std::size_t colon1 = problem->rfind(':', colon2 - 1);
        f2::Diagnostic d;
        d.message = problem->substr(error + 9);
        d.loc.file = problem->substr(0, colon1);
        std::from_chars(problem->data() + colon1 + 1, problem->data() + colon2, d.loc.line);
        std::from_chars(problem->data() + colon2 + 1, problem->data() + error, d.loc.column);
        return d;
    }
    return std::nullopt;
}

}  // namespace

extern "C" {

/// Parses `text` (UTF-8; empty: the default scene). Returns the diagnostics as
/// JSON: {"ok":bool,"lastFrame":N,"diagnostics":[{"file","line","column","markColumn",
/// "endColumn","severity","message"}]}: `f2 check`'s line, column and message;
/// [markColumn, endColumn) the bytes an editor marks, as the language server's
/// range (markedBytes). Columns are 1-based, in bytes. As `f2 check`, a
/// `/drive` without a finite value at a frame is an error too. The scene is
/// kept only without errors; otherwise the last good one stays.
const char* f2_set_scene(const char* text) {
    Module& m = module();
    const std::string_view source = *text ? std::string_view(text) : f2::defaultSceneText();
    f2::ParseResult result = f2::parseScene(source, kSceneName);
    if (result.scene) {
        if (std::optional<f2::Diagnostic> problem = driveProblem(*result.scene)) {
            result.diagnostics.push_back(std::move(*problem));
            result.scene.reset();
        }
    }
    const bool ok = result.scene.has_value();
    if (ok) {
        m.scene = std::move(result.scene);
        m.preparedFrame.reset();
    }
    std::string& out = m.text;
    out = "{\"ok\":";
    out += ok ? "true" : "false";
    out += ",\"lastFrame\":" + std::to_string(m.scene ? m.scene->lastFrame() : 0);
    out += ",\"diagnostics\":[";
    for (std::size_t i = 0; i < result.diagnostics.size(); ++i) {
        const f2::Diagnostic& d = result.diagnostics[i];
        const std::string_view line =
            d.loc.file == kSceneName ? lineOf(source, d.loc.line) : std::string_view{};
        const f2::ByteSpan span = f2::markedBytes(d, line);
        out += i ? ",{" : "{";
        out += "\"file\":";
        appendJsonString(out, d.loc.file);
        out += ",\"line\":" + std::to_string(d.loc.line);
        out += ",\"column\":" + std::to_string(d.loc.column);
        out += ",\"markColumn\":" + std::to_string(span.first + 1);
        out += ",\"endColumn\":" + std::to_string(span.first + span.length + 1);
        out += ",\"severity\":";
        out += d.severity == f2::Severity::Error ? "\"error\"" : "\"warning\"";
        out += ",\"message\":";
        appendJsonString(out, d.message);
        out += "}";
    }
    out += "]}";
    return out.c_str();
}

/// Renders rows [y0, y1) of frame `frame` (scene frames, may be fractional)
/// of the kept scene at width x height, through the scene's camera, as
/// `f2 render --frame` does, with `antialias` x `antialias` samples per pixel
/// (`--aa`). A look-around (the page's mouse drag, the viewer's orbit): the
/// camera turned by `yawDeg` and `pitchDeg` about a point in front of it and
/// its distance to that point times `zoom`; 0, 0, 1 is the scene's camera
/// itself. Returns (y1 - y0) * width RGBA pixels, or null without a scene,
/// with a frame that is not finite or with a bad size.
const std::uint8_t* f2_render(double frame, int width, int height, int y0, int y1, int antialias,
                              double yawDeg, double pitchDeg, double zoom) {
    Module& m = module();
    if (!m.scene || !std::isfinite(frame) || width < 1 || height < 1 || width > 16384 || height > 16384 ||
        y0 < 0 || y1 > height || y0 >= y1 || antialias < 1 || antialias > 16 || !std::isfinite(yawDeg) ||
        !std::isfinite(pitchDeg) || !(zoom > 0) || !std::isfinite(zoom))
        return nullptr;
    f2::RenderOptions options;
    options.antialias = antialias;
    options.firstRow = y0;
    options.endRow = y1;
    f2::Camera camera = f2::cameraAt(*m.scene, frame).resized(width, height);
    if (yawDeg != 0 || pitchDeg != 0 || zoom != 1) {
        // The same orbit in every worker: the target depends only on the scene and the frame.
        f2::OrbitCamera orbit =
            f2::OrbitCamera::fromCamera(camera, f2::orbitTargetDistance(*m.scene, camera));
        orbit.orbit(float(yawDeg), float(pitchDeg));
        orbit.zoom(float(zoom));
        camera = orbit.apply(camera);
    }
    if (m.preparedFrame == frame) {
        // The frame is evaluated and its BVH built: render()'s last steps only.
        m.renderer.trace(m.renderer.frame(), camera, m.image, options);
        f2::drawCaptions(m.image, m.scene->captions, frame);
    } else {
        m.renderer.render(*m.scene, frame, camera, m.image, options);
        m.preparedFrame = frame;
    }
    m.rgba.resize(std::size_t(y1 - y0) * std::size_t(width) * 4);
    std::uint8_t* p = m.rgba.data();
    for (int y = y0; y < y1; ++y) {
        for (int x = 0; x < width; ++x, p += 4) {
            const f2::Rgb8 c = m.image.at(x, y);
            p[0] = c.r;
            p[1] = c.g;
            p[2] = c.b;
            p[3] = 255;
        }
    }
    return m.rgba.data();
}

/// "wasm SIMD" or "scalar": which build the page loaded.
const char* f2_build_name() {
#if defined(__wasm_simd128__)
    return "wasm SIMD";
#else
    return "scalar";
#endif
}

}  // extern "C"
