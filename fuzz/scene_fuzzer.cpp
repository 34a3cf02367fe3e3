// libFuzzer target over the scene language and everything a parsed scene feeds:
// parse (with the real limits and with small ones), then evaluate the animation
// at a few times, build the BVH and trace a tiny image with one thread.
//
// Invariants checked (a violation aborts, so libFuzzer keeps the input):
//  - a result has a scene exactly when it has no error;
//  - every diagnostic has a place (LINE >= 1, COL >= 1, LINE within the text
//    for the input itself; an `/include`d file is one the result lists) and a
//    message without raw control bytes;
//  - the number of kept diagnostics respects maxErrors / maxWarnings;
//  - every traced sample is finite (no NaN or infinity reaches a pixel).
//
// Build: cmake --preset fuzz && cmake --build --preset fuzz
// Run:   fuzz/run.sh SECONDS
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/anim/frame_builder.h"
#include "core/parse/parser.h"
#include "core/render/camera.h"
#include "core/render/renderer.h"

namespace {

[[noreturn]] void fail(const char* what, const std::string& detail) {
    std::fprintf(stderr, "f2 fuzz invariant broken: %s\n%s\n", what, detail.c_str());
    std::abort();
}

int lineCount(std::string_view text) {
    int n = 1;
    for (char c : text) n += c == '\n';
    return n;
}

void checkResult(const f2::ParseResult& r, std::string_view text, const f2::ParseLimits& limits) {
    const bool errors = f2::hasErrors(r.diagnostics);
    if (r.ok() == errors) fail("ok() must equal !hasErrors()", std::to_string(r.diagnostics.size()));
    const int lines = lineCount(text);
    std::size_t nErrors = 0, nWarnings = 0;
    for (const f2::Diagnostic& d : r.diagnostics) {
        const std::string f = d.format();
        const bool input = d.loc.file == "fuzz.f2";
        if (d.loc.line < 1 || d.loc.column < 1 || (input && d.loc.line > lines)) {
            fail("diagnostic outside the text", f);
        }
        if (!input && std::find(r.files.begin(), r.files.end(), d.loc.file) == r.files.end()) {
            fail("diagnostic names a file the parse did not read", f);
        }
        for (unsigned char c : d.message) {
            if (c < 0x20 || c == 0x7F) fail("raw control byte in a message", f);
        }
        (d.severity == f2::Severity::Error ? nErrors : nWarnings) += 1;
    }
    // +1: the "too many errors" line; +1: the "N more warnings" line.
    if (nErrors > limits.maxErrors + 1) fail("more errors than maxErrors", std::to_string(nErrors));
    if (nWarnings > limits.maxWarnings + 1) fail("more warnings than maxWarnings", std::to_string(nWarnings));
}

void checkFinite(const f2::Vec3& c, double t, float px, float py) {
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
        fail("non-finite sample", "t=" + std::to_string(t) + " pixel " + std::to_string(px) + "," +
                                      std::to_string(py) + " -> " + std::to_string(c.x) + " " +
                                      std::to_string(c.y) + " " + std::to_string(c.z));
    }
}

void renderAt(const f2::SceneDesc& scene, double t) {
    static f2::Renderer renderer(1);
    // Small image whatever the scene asks for; the field of view is kept.
    const f2::Camera camera = f2::cameraAt(scene, t).resized(8, 6);
    f2::Image image;
    renderer.render(scene, t, camera, image);
    if (image.width != 8 || image.height != 6 || image.pixels.size() != 48) fail("wrong image size", "");
    const f2::PreparedFrame& frame = renderer.frame();
    if (frame.primitives.size() != scene.primitiveCount()) fail("primitive count", "");
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 8; ++i) {
            const float px = float(i) + 0.5f, py = float(j) + 0.5f;
            checkFinite(f2::renderSample(frame, camera, px, py), t, px, py);
        }
}

/// Largest coordinate or size of the scene (positions, sizes, key positions
/// and offsets, the camera's eye).
double largestCoordinate(const f2::SceneDesc& scene) {
    double m = 0;
    auto grow = [&m](const f2::Vec3& v) {
        m = std::max({m, double(std::fabs(v.x)), double(std::fabs(v.y)), double(std::fabs(v.z))});
    };
    grow(scene.camera.pose.position);
    for (const f2::Key& k : scene.camera.track.keys) grow(k.pose.position);
    for (const f2::SceneObject& o : scene.objects) {
        grow(o.size);
        grow(o.rest.position);
        for (const f2::Key& k : o.track.keys) grow(k.pose.position);
        for (const f2::Track& t : o.partTracks)
            for (const f2::Key& k : t.keys) grow(k.pose.position);
    }
    return m;
}

/// Scenes with larger coordinates are parsed but not rendered; no limit by
/// default. Sessions 1-2 used 1e15 while core finding F1 was open
/// (tests/data/fuzz/core_bvh_nan_centroid.f2: coordinates near FLT_MAX made
/// Bvh::build index its bins with int(NaN); fixed in 3d8ca4f).
double renderMaxCoordinate() {
    static const double limit = [] {
        const char* env = std::getenv("F2_FUZZ_RENDER_MAX_COORD");
        return env ? std::strtod(env, nullptr) : HUGE_VAL;
    }();
    return limit;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);

    // Small limits: every limit path is reachable with a few KB of input.
    f2::ParseLimits small;
    small.maxImageSide = 64;
    small.maxImagePixels = 2048;
    small.maxObjects = 8;
    small.maxKeyFrame = 1000;
    small.maxKeyLines = 16;
    small.maxFps = 60;
    small.maxLineBytes = 200;
    small.maxSceneBytes = 3000;
    small.maxErrors = 5;
    small.maxWarnings = 3;
    small.maxExpandedLines = 500;
    small.maxLoopDepth = 4;
    small.maxIncludeDepth = 2;
    checkResult(f2::parseScene(text, "fuzz.f2", small), text, small);

    // The real limits; only a scene that parses is rendered. Except the
    // expanded lines: a 40-byte loop may legitimately read 10,000,000 lines,
    // which takes longer than the fuzzer's timeout under the sanitizers (the
    // limit's code is the same at any value).
    f2::ParseLimits real;
    real.maxExpandedLines = 200'000;
    const f2::ParseResult r = f2::parseScene(text, "fuzz.f2", real);
    checkResult(r, text, real);
    if (!r.ok()) return 0;
    const f2::SceneDesc& scene = *r.scene;
    const int last = scene.lastFrame();
    if (last < 0 || last > real.maxKeyFrame) fail("lastFrame out of range", std::to_string(last));
    // Bounded work per input: a few hundred primitives x 48 pixels is quick.
    if (scene.primitiveCount() > 2000) return 0;
    if (!(largestCoordinate(scene) <= renderMaxCoordinate())) return 0;
    for (double t : {0.0, 0.5 * last + 0.25, double(last), double(last) + 1.0}) renderAt(scene, t);
    return 0;
}
