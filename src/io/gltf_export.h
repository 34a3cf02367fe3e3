#pragma once
/// The whole animation of a scene as glTF 2.0 (docs/output.md, "Into other
/// tools"): a node tree of objects, model parts and shapes, meshes
/// tessellated from the exact primitives, PBR materials approximating the
/// Phong looks, KHR_lights_punctual lights, the camera, and one animation
/// sampled at every frame. Written as one binary .glb, or as a .gltf with
/// its buffer in a .bin beside it.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/scene/scene_desc.h"

namespace f2 {

struct GltfOptions {
    int width = 800, height = 600;  ///< the image size the camera's aspect ratio and yfov come from
    int tessellation = 32;          ///< segments around a sphere or cylinder (tessellate.h)
    /// The buffer's URI (a .gltf's `buffers[0].uri`, uriOfFileName); empty: a
    /// .glb, whose buffer is its BIN chunk.
    std::string bufferUri;
    std::string source;  ///< the scene's name, in `asset.extras`
    /// Colour, light intensity and camera `d` keys and drives as channels of
    /// KHR_animation_pointer (sampled at every frame; without it they are
    /// left out, with a warning): `f2 export --gltf-pointer`.
    bool pointer = false;
};

struct GltfDocument {
    std::string json;                   ///< the glTF JSON, no buffer inside
    std::vector<std::uint8_t> bin;      ///< buffers[0], padded to 4 bytes
    std::vector<std::string> warnings;  ///< what the format leaves out, one sentence each
    std::size_t nodes = 0, meshes = 0, materials = 0, channels = 0;
};

/// The scene from frame 0 to its last frame (SceneDesc::lastFrame), times in
/// seconds (frames / fps).
GltfDocument gltfScene(const SceneDesc& scene, const GltfOptions& options);

/// A file name as a relative URI (GltfOptions::bufferUri): every byte but
/// RFC 3986's unreserved ones percent-encoded, so `a b#1.bin` stays a name.
std::string uriOfFileName(std::string_view name);

/// The document as a binary glTF file (.glb): header, JSON chunk, BIN chunk.
std::string glbBytes(const GltfDocument& document);

}  // namespace f2
