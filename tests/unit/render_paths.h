#pragma once
/// The packet path (Renderer::render) against the single-ray reference path
/// (traceReference), for tests of shading features.
#include <gtest/gtest.h>

#include <string>

#include "core/render/renderer.h"
#include "test_scenes.h"

namespace f2::test {

/// The packet path and the reference path give the same bytes for `text`'s
/// scene at frame 0: materials without highlights (whose pow() differs), so
/// every pixel must be equal.
inline void expectIdenticalPaths(const std::string& text, const std::string& what) {
    SceneDesc scene = sceneFromText(text);
    Renderer renderer(2);
    Image fast, reference;
    Camera camera = Camera::fromDesc(scene.camera);
    renderer.render(scene, 0, camera, fast);
    traceReference(renderer.frame(), camera, reference);
    ASSERT_EQ(fast.pixels.size(), reference.pixels.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < fast.pixels.size(); ++i)
        differing += !(fast.pixels[i] == reference.pixels[i]);
    EXPECT_EQ(differing, 0u) << what;
}

}  // namespace f2::test
