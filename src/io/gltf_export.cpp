#include "io/gltf_export.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <tuple>

#include "core/anim/camera_motion.h"
#include "core/anim/frame_builder.h"
#include "core/anim/light_evaluation.h"
#include "core/anim/track.h"
#include "core/scene/models.h"
#include "io/frame_primitives.h"
#include "io/gltf_frame.h"
#include "io/png_writer.h"
#include "io/tessellate.h"

namespace f2 {

namespace {
using json = nlohmann::json;

// glTF's enumerations.
constexpr int kFloat = 5126, kUnsignedShort = 5123, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kNearest = 9728, kRepeat = 10497;

/// How long before a step key (frames) the held value is sampled again, so
/// that LINEAR interpolation jumps there instead of sliding over a frame.
constexpr double kJumpFrames = 1e-3;

/// A float as the shortest decimal that reads back to it (JSON numbers are
/// doubles: 0.3f would otherwise print as 0.30000001192092896).
json number(float value) {
    if (value == 0) return 0.0;
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    double out = 0;
    std::from_chars(text, end, out);
    return out;
}

json numbers(std::initializer_list<float> values) {
    json out = json::array();
    for (float v : values) out.push_back(number(v));
    return out;
}

/// sRGB-encoded 0..255 to glTF's linear factors.
float linearFromSrgb(float c255) {
    const double c = c255 / 255.0;
    return float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

/// The one buffer, and the views and accessors into it.
class BufferBuilder {
   public:
    std::vector<std::uint8_t> bytes;
    json views = json::array(), accessors = json::array();

    /// `values` as an accessor of `type` ("SCALAR", "VEC3", ...) of `components` floats each.
    int floats(const std::vector<float>& values, const char* type, int components, int target, bool bounds) {
        const int view = addView(values.data(), values.size() * sizeof(float), target);
        json accessor = {{"bufferView", view},
                         {"componentType", kFloat},
                         {"count", values.size() / std::size_t(components)},
                         {"type", type}};
        if (bounds) {
            std::vector<float> lo(values.begin(), values.begin() + components), hi = lo;
            for (std::size_t i = 0; i < values.size(); ++i) {
                const std::size_t c = i % std::size_t(components);
                lo[c] = std::min(lo[c], values[i]);
                hi[c] = std::max(hi[c], values[i]);
            }
            accessor["min"] = json::array();
            accessor["max"] = json::array();
            for (int c = 0; c < components; ++c) {
                accessor["min"].push_back(number(lo[std::size_t(c)]));
                accessor["max"].push_back(number(hi[std::size_t(c)]));
            }
        }
        accessors.push_back(std::move(accessor));
        return int(accessors.size() - 1);
    }

    /// Triangle indices, 16 bits when they fit (65535 is the restart value: not used).
    int indices(const std::vector<std::uint32_t>& values, std::size_t vertexCount) {
        const bool narrow = vertexCount < 65535;
        int view;
        if (narrow) {
            std::vector<std::uint16_t> shorts(values.begin(), values.end());
            view = addView(shorts.data(), shorts.size() * 2, kElementArrayBuffer);
        } else {
            view = addView(values.data(), values.size() * 4, kElementArrayBuffer);
        }
        accessors.push_back({{"bufferView", view},
                             {"componentType", narrow ? kUnsignedShort : kUnsignedInt},
                             {"count", values.size()},
                             {"type", "SCALAR"}});
        return int(accessors.size() - 1);
    }

    /// A view of `size` bytes of `data`; `target` 0: none (animation data, images).
    int addView(const void* data, std::size_t size, int target) {
        bytes.resize((bytes.size() + 3) & ~std::size_t(3), 0);  // every view 4-aligned
        json view = {{"buffer", 0}, {"byteOffset", bytes.size()}, {"byteLength", size}};
        if (target) view["target"] = target;
        const auto* p = static_cast<const std::uint8_t*>(data);
        bytes.insert(bytes.end(), p, p + size);
        views.push_back(std::move(view));
        return int(views.size() - 1);
    }
};

/// A node whose local transform (in F2's frame) changes: sampled at `times`
/// (frames), interpolated as `step` says.
struct MovingNode {
    int node = 0;
    std::function<Transform(double)> localAt;
    std::vector<double> times;
    bool step = false;
};

/// Whether every segment of a track holds its key until the next one.
bool allSteps(const Track& track) {
    for (std::size_t i = 0; i + 1 < track.keys.size(); ++i)
        if (track.modeAfter(i).mode != Interpolation::Step) return false;
    return true;
}

/// Sorted, unique, within [0, last].
std::vector<double> tidy(std::vector<double> times, double last) {
    std::erase_if(times, [last](double t) { return !(t >= 0 && t <= last); });
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    return times;
}

/// A bounding radius of a shape about its centre.
float radiusOf(ShapeKind kind, Vec3 size) {
    switch (kind) {
        case ShapeKind::Sphere:
            return size.x;
        case ShapeKind::Cylinder:
            return std::hypot(size.x, size.y / 2);
        case ShapeKind::Box:
            return length(size) / 2;
    }
    return 0;
}

class GltfBuilder {
   public:
    GltfBuilder(const SceneDesc& scene, const GltfOptions& options) : scene_(scene), options_(options) {
        last_ = scene.lastFrame();
        for (int f = 0; f <= last_; ++f) frames_.push_back(f);
        measureScene();
    }

    GltfDocument build() {
        if (options_.pointer) markKeyedColours();
        objects();
        camera();
        lights();
        visibility();
        animation();
        if (options_.pointer) pointerChannels();
        warnings();
        return finish();
    }

   private:
    const SceneDesc& scene_;
    const GltfOptions& options_;
    int last_ = 0;
    std::vector<double> frames_;
    Vec3 centre_;
    float size_ = 1;  ///< the diagonal of the scene's bounds at frame 0

    BufferBuilder buffer_;
    std::vector<json> nodes_;
    std::vector<int> parentOf_;
    json meshes_ = json::array(), materials_ = json::array(), lights_ = json::array();
    json cameras_ = json::array(), samplers_ = json::array(), channels_ = json::array();
    std::vector<MovingNode> moving_;
    std::vector<std::string> warnings_;
    bool emissiveStrength_ = false;
    bool pointerUsed_ = false;
    /// --gltf-pointer: each shape (object, index among its primitives) a
    /// `colour` track reaches, and the material of its own it gets.
    std::map<std::pair<std::size_t, std::size_t>, int> keyedMaterial_;
    /// --gltf-pointer: each named light's glTF light, its written intensity
    /// and the factor from F2's intensity to glTF's (lux or candela).
    struct PointerLight {
        std::size_t light = 0;
        std::int32_t motion = 0;
        float written = 0, factor = 1;
    };
    std::vector<PointerLight> pointerLights_;

    /// Per object: its node, each part's moving node, each shape's node.
    std::vector<int> objectNode_;
    std::vector<std::vector<int>> motionNode_, shapeNode_;

    /// A tessellated shape's accessors (NORMAL is position + 1), shared by its meshes.
    struct Geometry {
        int id = 0, position = 0, indices = 0;
    };
    std::map<std::tuple<ShapeKind, float, float, float>, Geometry> geometry_;
    std::map<std::tuple<int, int, int>, int> meshOf_;  // (geometry id, material, uv or -1) -> mesh
    using MaterialKey = std::tuple<std::uint8_t, std::uint8_t, std::uint8_t, float, float, float, float, bool,
                                   std::uint8_t, std::uint8_t, std::uint8_t>;
    std::map<MaterialKey, int> materialOf_;
    std::map<std::vector<float>, int> timeAccessor_;
    json images_ = json::array(), textures_ = json::array();
    std::map<std::tuple<std::uint8_t, std::uint8_t, std::uint8_t, std::uint8_t, std::uint8_t, std::uint8_t>,
             int>
        textureOf_;
    std::map<std::tuple<float, float, float, float>, int> checkerUvOf_;
    /// A checkered sphere's or cylinder's triangles by cell parity (index accessors, -1: none).
    std::map<std::tuple<ShapeKind, float, float, float, float>, std::array<int, 2>> checkerSplitOf_;

    void measureScene() {
        Vec3 lo{1e30f, 1e30f, 1e30f}, hi = -lo;
        for (const PlacedPrimitive& p : framePrimitives(scene_, 0)) {
            const float r = radiusOf(p.kind, p.size);
            const Vec3 c = p.worldFromLocal.translation;
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], c[a] - r);
                hi[a] = std::max(hi[a], c[a] + r);
            }
        }
        if (!(lo.x <= hi.x)) return;  // nothing to see
        centre_ = (lo + hi) * 0.5f;
        size_ = std::max(length(hi - lo), 1e-6f);
    }

    int addNode(json node, int parent) {
        nodes_.push_back(std::move(node));
        parentOf_.push_back(parent);
        return int(nodes_.size() - 1);
    }

    /// Writes a node's translation and rotation (left out when they are the identity).
    void setPose(int node, const Transform& local) {
        const GltfPose pose = gltfPoseOf(local);
        json& n = nodes_[std::size_t(node)];
        n.erase("translation");
        n.erase("rotation");
        if (pose.translation != std::array<float, 3>{})
            n["translation"] = numbers({pose.translation[0], pose.translation[1], pose.translation[2]});
        if (pose.rotation != std::array<float, 4>{0, 0, 0, 1})
            n["rotation"] = numbers({pose.rotation[0], pose.rotation[1], pose.rotation[2], pose.rotation[3]});
    }

    /// A node that follows `track` (pose keys): sampled at every frame and key
    /// (LINEAR, the held value again just before a step ends), or at its keys
    /// alone (STEP) when every key is a step. A node that does not move
    /// gets its pose and no channel (animation()). `baked`: it also moves
    /// with what it rides on or looks at, so every frame whatever its keys
    /// (as a driven track, SPEC 10.7).
    void follow(int node, const Track& track, std::function<Transform(double)> localAt, bool baked = false,
                std::vector<double> extra = {}) {
        MovingNode moving{node, std::move(localAt), {}, false};
        // A drive (SPEC 10.7) moves its target whatever the keys.
        const bool continuous = baked || track.drives;
        if (track.keys.size() < 2 && !continuous) {
            moving.times = {0};  // one pose for ever: no need to look at every frame
        } else if (allSteps(track) && !continuous) {
            moving.step = true;
            for (const Key& k : track.keys) moving.times.push_back(k.time);
        } else {
            moving.times = frames_;
            for (std::size_t i = 0; i < track.keys.size(); ++i) {
                moving.times.push_back(track.keys[i].time);
                if (i > 0 && track.modeAfter(i - 1).mode == Interpolation::Step)
                    moving.times.push_back(track.keys[i].time - kJumpFrames);
            }
            moving.times.insert(moving.times.end(), extra.begin(), extra.end());
        }
        moving.times = tidy(std::move(moving.times), last_);
        if (moving.times.empty()) moving.times.push_back(0);
        moving_.push_back(std::move(moving));
    }

    // ---- 1. the node tree -------------------------------------------------

    void objects() {
        const std::size_t n = scene_.objects.size();
        objectNode_.resize(n);
        motionNode_.resize(n);
        shapeNode_.resize(n);
        for (std::size_t i = 0; i < n; ++i) object(i);
        // Parents once every object has its nodes: a ride may name a later object.
        for (std::size_t i = 0; i < n; ++i) {
            const SceneObject& object = scene_.objects[i];
            if (!object.attachedTo || !object.attachChanges.empty()) continue;
            const FrameRef mount = *object.attachedTo;
            parentOf_[std::size_t(objectNode_[i])] = mount.part < 0
                                                         ? objectNode_[mount.object]
                                                         : motionNode_[mount.object][std::size_t(mount.part)];
        }
    }

    void object(std::size_t i) {
        const SceneObject& object = scene_.objects[i];
        const int node = objectNode_[i] = addNode({{"name", object.name}}, -1);
        if (!object.attachChanges.empty()) {
            // Its ride changes (SPEC 10.7): no parent holds for the whole
            // animation, so the world frame is baked on a top-level node.
            std::vector<double> jumps;
            for (const AttachChange& c : object.attachChanges)
                jumps.insert(jumps.end(), {c.time, c.time - kJumpFrames});
            follow(
                node, object.track,
                [this, i](double t) {
                    return worldFromRef(scene_, FrameRef{std::uint32_t(i), -1}, t);
                },
                true, std::move(jumps));
        } else {
            follow(node, object.track, [&object](double t) { return objectFrame(object, t); });
        }
        if (!object.model) {
            // `name.shape`: node names stay unique (Blender and three.js rename duplicates).
            shapeNode_[i].push_back(shapeNode(object.name + ".shape", object.name, shapeKindOf(object.kind),
                                              object.size, object.appearance[0], node, {i, 0}));
            return;
        }
        const ModelType& model = *object.model;
        for (std::size_t p = 0; p < model.parts.size(); ++p) {
            const ModelPart& part = model.parts[p];
            const std::string name = object.name + "." + part.name;
            const int parent = part.parent < 0 ? node : motionNode_[i][std::size_t(part.parent)];
            // The pivot and rest rotation, fixed; the keys' offset and rotation
            // on a child. SPEC 10.1's translate(pivot + offset) · rest · rot is
            // translate(pivot) · rest · translate(rest⁻¹ · offset) · rot.
            const Mat3 rest = part.rest ? *part.rest : Mat3{};
            const int pivot = addNode({{"name", name}}, parent);
            setPose(pivot, Transform{rest, part.pivot});
            const int motion = addNode({{"name", name + ".pose"}}, pivot);
            motionNode_[i].push_back(motion);
            const Mat3 unrest = rest.transposed();
            const Track& track = object.partTracks[p];
            follow(motion, track, [&track, unrest](double t) {
                const Pose pose = evaluateTrack(track, t, Pose{});
                return Transform{rotationFromEulerDegrees(pose.rotation), unrest * pose.position};
            });
        }
        for (std::size_t k = 0; k < model.shapes.size(); ++k) {
            const ModelShape& shape = model.shapes[k];
            const std::string label =
                object.name + "." + model.parts[std::size_t(shape.part)].name + "." + shape.name;
            const int s = shapeNode(label, label, shape.kind, shape.size, object.appearance[k],
                                    motionNode_[i][std::size_t(shape.part)], {i, k});
            setPose(s, Transform{shape.turn ? *shape.turn : Mat3{}, shape.centre});
            shapeNode_[i].push_back(s);
        }
    }

    /// A node holding a shape's mesh; its scale is the shape's visibility.
    /// `label`: the shape's name in the language, as POV-Ray export comments
    /// give it, for tools that match the two up (extras.f2Shape).
    /// `shape`: the object and the shape's index among its primitives.
    int shapeNode(const std::string& name, const std::string& label, ShapeKind kind, Vec3 size,
                  const Appearance& look, int parent, std::pair<std::size_t, std::size_t> shape) {
        // A shape whose colour is keyed (--gltf-pointer) gets a material of its own.
        const bool keyed = keyedMaterial_.contains(shape);
        const int mesh = meshFor(kind, size, look, keyed);
        if (keyed) keyedMaterial_[shape] = meshes_[std::size_t(mesh)]["primitives"][0]["material"].get<int>();
        return addNode({{"name", name}, {"mesh", mesh}, {"extras", {{"f2Shape", label}}}}, parent);
    }

    // ---- 2. meshes ----------------------------------------------------------

    /// `own`: the mesh gets a material no other mesh shares.
    int meshFor(ShapeKind kind, Vec3 size, const Appearance& look, bool own = false) {
        const auto key = std::make_tuple(kind, size.x, size.y, size.z);
        auto found = geometry_.find(key);
        if (found == geometry_.end()) {
            TriangleMesh mesh = tessellate(kind, size, options_.tessellation);
            // Into glTF's frame: z mirrored, so each triangle's order is
            // reversed to stay counter-clockwise seen from outside.
            std::vector<float> positions, normals;
            for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
                const Vec3 p = gltfFromF2(mesh.positions[v]), nrm = gltfFromF2(mesh.normals[v]);
                positions.insert(positions.end(), {p.x, p.y, p.z});
                normals.insert(normals.end(), {nrm.x, nrm.y, nrm.z});
            }
            for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
                std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
            Geometry g{int(geometry_.size()), buffer_.floats(positions, "VEC3", 3, kArrayBuffer, true), 0};
            buffer_.floats(normals, "VEC3", 3, kArrayBuffer, false);
            g.indices = buffer_.indices(mesh.indices, mesh.positions.size());
            found = geometry_.emplace(key, g).first;
        }
        const Geometry& g = found->second;
        // A box's checker is exact as a texture (checkerUv); on a curved shape
        // its cells are no squares of any map: its triangles split by cell.
        const bool checkered = look.checker.size > 0, textured = checkered && kind == ShapeKind::Box;
        if (checkered && !textured) return checkerSplitMesh(kind, size, look, g, own);
        const int material = materialFor(look, textured, own);
        const int uv = textured ? checkerUv(size, look.checker.size) : -1;
        const auto meshKey = std::make_tuple(g.id, material, uv);
        if (auto m = meshOf_.find(meshKey); m != meshOf_.end()) return m->second;
        json attributes = {{"POSITION", g.position}, {"NORMAL", g.position + 1}};
        if (uv >= 0) attributes["TEXCOORD_0"] = uv;
        meshes_.push_back(
            {{"name", std::string(shapeKindName(kind))},
             {"primitives", {{{"attributes", attributes}, {"indices", g.indices}, {"material", material}}}}});
        return meshOf_[meshKey] = int(meshes_.size() - 1);
    }

    /// A checkered sphere or cylinder (docs/output.md): two primitives over
    /// the shape's vertices, the triangles whose centre lies in an even cell
    /// of F2's 3D checker (docs/rendering.md, in the shape's own frame) in the
    /// paint's material, the others in the checker colour's. Exact at the
    /// triangles' centres; a cell's edge follows the triangles' edges.
    int checkerSplitMesh(ShapeKind kind, Vec3 size, const Appearance& look, const Geometry& g, bool own) {
        const float s = look.checker.size;
        const auto key = std::make_tuple(kind, size.x, size.y, size.z, s);
        auto found = checkerSplitOf_.find(key);
        if (found == checkerSplitOf_.end()) {
            const TriangleMesh mesh = tessellate(kind, size, options_.tessellation);
            std::array<std::vector<std::uint32_t>, 2> byParity;
            const auto parity = [s](float x) {
                const float cell = std::floor(x / s);
                return int(cell - 2 * std::floor(cell / 2));
            };
            for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
                const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
                const Vec3 centre = (mesh.positions[a] + mesh.positions[b] + mesh.positions[c]) / 3.0f;
                const int odd = (parity(centre.x) + parity(centre.y) + parity(centre.z)) % 2;
                byParity[std::size_t(odd)].insert(byParity[std::size_t(odd)].end(), {a, c, b});  // mirrored
            }
            std::array<int, 2> accessors{-1, -1};
            for (int k = 0; k < 2; ++k)
                if (!byParity[std::size_t(k)].empty())
                    accessors[std::size_t(k)] =
                        buffer_.indices(byParity[std::size_t(k)], mesh.positions.size());
            found = checkerSplitOf_.emplace(key, accessors).first;
        }
        Appearance even = look, odd = look;
        even.checker.size = odd.checker.size = 0;
        odd.color = look.checker.color;
        const std::array<int, 2> materials{materialFor(even, false, own), materialFor(odd, false, own)};
        const auto meshKey = std::make_tuple(g.id, materials[0], -2 - materials[1]);  // no uv is ever < -1
        if (auto m = meshOf_.find(meshKey); m != meshOf_.end()) return m->second;
        json primitives = json::array();
        for (int k = 0; k < 2; ++k) {
            if (found->second[std::size_t(k)] < 0) continue;
            primitives.push_back({{"attributes", {{"POSITION", g.position}, {"NORMAL", g.position + 1}}},
                                  {"indices", found->second[std::size_t(k)]},
                                  {"material", materials[std::size_t(k)]}});
        }
        meshes_.push_back(
            {{"name", std::string(shapeKindName(kind)) + " checker"}, {"primitives", primitives}});
        return meshOf_[meshKey] = int(meshes_.size() - 1);
    }

    /// Texture coordinates of a box (tessellate's vertices, in its order)
    /// that lay checkerTexture's 2 x 2 texels on it as F2's 3D checker of
    /// cell `s` (docs/rendering.md): on a face across axis a, (u, v) = its
    /// other two coordinates / 2s, so a texel is a cell; the cell parity
    /// along a, constant over the face (read just inside, as F2 does), shifts
    /// u by one texel.
    int checkerUv(Vec3 size, float s) {
        const auto key = std::make_tuple(size.x, size.y, size.z, s);
        if (auto found = checkerUvOf_.find(key); found != checkerUvOf_.end()) return found->second;
        const TriangleMesh box = tessellate(ShapeKind::Box, size, kMinTessellation);
        std::vector<float> uv;
        for (std::size_t v = 0; v < box.positions.size(); ++v) {
            const Vec3 p = box.positions[v], n = box.normals[v];
            const int a = std::fabs(n.x) > 0.5f ? 0 : std::fabs(n.y) > 0.5f ? 1 : 2;
            const float inside = p[a] - n[a] * s * 1e-4f;
            const float shift = std::fmod(std::fabs(std::floor(inside / s)), 2.0f) * 0.5f;
            uv.insert(uv.end(), {p[(a + 1) % 3] / (2 * s) + shift, p[(a + 2) % 3] / (2 * s)});
        }
        const int accessor = buffer_.floats(uv, "VEC2", 2, kArrayBuffer, false);
        return checkerUvOf_[key] = accessor;
    }

    /// The 2 x 2 texels of a checker (`first` where column + row is even),
    /// as a PNG in the buffer, sampled NEAREST and REPEAT.
    int checkerTexture(Color8 first, Color8 second) {
        const auto key = std::make_tuple(first.r, first.g, first.b, second.r, second.g, second.b);
        if (auto found = textureOf_.find(key); found != textureOf_.end()) return found->second;
        Image image;
        image.resize(2, 2);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x) {
                const Color8 c = (x + y) % 2 ? second : first;
                image.at(x, y) = {c.r, c.g, c.b};  // sRGB, as glTF's base colour textures are
            }
        images_.push_back({{"bufferView", pngView(image)}, {"mimeType", "image/png"}});
        textures_.push_back({{"sampler", 0}, {"source", images_.size() - 1}});
        return textureOf_[key] = int(textures_.size() - 1);
    }

    int pngView(const Image& image) {
        char* data = nullptr;
        std::size_t size = 0;
        std::FILE* stream = open_memstream(&data, &size);
        std::string error;
        const bool written = stream && writePng(image, stream, error);
        if (stream) std::fclose(stream);  // sets data and size
        std::vector<std::uint8_t> bytes(data, data + (written ? size : 0));
        std::free(data);
        return buffer_.addView(bytes.data(), bytes.size(), 0);
    }

    // ---- 3. materials -------------------------------------------------------

    /// `textured`: the checker as a texture (a box's), else the first colour.
    int materialFor(const Appearance& look, bool textured, bool own = false) {
        const Color8 c = look.color, c2 = textured ? look.checker.color : Color8{0, 0, 0};
        const Material& m = look.material;
        // What the material is made of (not ka or kd).
        const MaterialKey key{c.r, c.g, c.b, m.ks, m.n, m.reflection, m.emission, textured, c2.r, c2.g, c2.b};
        if (auto found = materialOf_.find(key); !own && found != materialOf_.end()) return found->second;
        const float r = linearFromSrgb(c.r), g = linearFromSrgb(c.g), b = linearFromSrgb(c.b);
        // Phong's exponent n as a microfacet roughness (Blinn-Phong n ~ 2/α² - 2,
        // roughness = √α), weighed by how much highlight ks asks for; a mirror
        // is metallic and smooth (docs/output.md, "Into other tools").
        const float mirror = std::clamp(m.reflection, 0.0f, 1.0f);
        const float phong = float(std::sqrt(std::sqrt(2.0 / (double(m.n) + 2.0))));
        float roughness = 1.0f - std::clamp(m.ks, 0.0f, 1.0f) * (1.0f - phong);
        roughness = std::clamp(std::min(roughness, 1.0f - mirror), 0.0f, 1.0f);
        json material = {
            {"name", "paint " + std::to_string(c.r) + " " + std::to_string(c.g) + " " + std::to_string(c.b)},
            {"pbrMetallicRoughness",
             {{"baseColorFactor", numbers({r, g, b, 1.0f})},
              {"metallicFactor", number(mirror)},
              {"roughnessFactor", number(roughness)}}}};
        if (m.emission > 0) {
            const float e = std::min(m.emission, 1.0f);
            material["emissiveFactor"] = numbers({r * e, g * e, b * e});
            if (m.emission > 1) {
                material["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] =
                    number(m.emission);
                emissiveStrength_ = true;
            }
        }
        if (textured) {
            json& pbr = material["pbrMetallicRoughness"];
            pbr.erase("baseColorFactor");  // the texture's colours, as they are
            pbr["baseColorTexture"] = {{"index", checkerTexture(c, c2)}};
            material["name"] = material["name"].get<std::string>() + " checker " + std::to_string(c2.r) +
                               " " + std::to_string(c2.g) + " " + std::to_string(c2.b);
        }
        materials_.push_back(std::move(material));
        if (own) return int(materials_.size() - 1);
        return materialOf_[key] = int(materials_.size() - 1);
    }

    // ---- the camera -----------------------------------------------------------

    void camera() {
        const CameraDesc& desc = scene_.camera;
        const double w = options_.width, h = options_.height;
        const double d = cameraDistanceAt(scene_, 0);
        // SPEC 2: the screen is 1 wide and h/w high at distance d.
        cameras_.push_back({{"name", "camera"},
                            {"type", "perspective"},
                            {"perspective",
                             {{"aspectRatio", number(float(w / h))},
                              {"yfov", number(float(2.0 * std::atan(h / (2.0 * w * d))))},
                              {"znear", number(size_ * 1e-4f)}}}});
        const int node = addNode({{"name", "camera"}, {"camera", 0}}, -1);
        follow(
            node, desc.track, [this](double t) { return cameraFrameAt(scene_, t); },
            desc.attachedTo || desc.lookAt);
    }

    // ---- 4. lights ------------------------------------------------------------

    /// A light's node: at `position`, its -Z (glTF's light direction) along `direction`.
    /// `written`, `factor`: its intensity in F2 and the factor to glTF's unit.
    void lightNode(const std::string& name, json light, std::int32_t motion, Vec3 position, Vec3 direction,
                   float written, float factor) {
        lights_.push_back(std::move(light));
        if (motion != kStillLight) pointerLights_.push_back({lights_.size() - 1, motion, written, factor});
        const int node = addNode(
            {{"name", name}, {"extensions", {{"KHR_lights_punctual", {{"light", lights_.size() - 1}}}}}}, -1);
        // F2's +z is glTF's -Z (gltf_frame.h): turn +z onto the direction.
        const Transform own{direction == Vec3{} ? Mat3{}
                                                : rotationFromEulerDegrees(lookAtRotation(
                                                      direction.x, direction.y, direction.z, 0)),
                            position};
        if (motion == kStillLight) {
            setPose(node, own);
            return;
        }
        const LightMotion& m = scene_.lightMotions[std::size_t(motion)];
        follow(
            node, m.track, [this, &m, own](double t) { return lightFrameAt(scene_, m, t) * own; },
            m.attachedTo.has_value());
    }

    std::string lightName(std::int32_t motion, const char* kind, std::size_t index) const {
        if (motion != kStillLight) return scene_.lightMotions[std::size_t(motion)].name;
        return std::string(kind) + " " + std::to_string(index + 1);
    }

    /// F2 lights a colour C facing a light of intensity I as C·I (SPEC 3); a
    /// Lambertian surface of albedo C under an illuminance E (lux) has the
    /// radiance C·E/π. So E = π·I: a physically based viewer shows F2's values.
    static float lux(float intensity) { return float(kPi) * intensity; }

    void lights() {
        for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
            const DirectionalLight& l = scene_.lights[i];
            lightNode(lightName(l.motion, "dir_light", i),
                      {{"type", "directional"}, {"intensity", number(lux(l.intensity))}}, l.motion, Vec3{},
                      l.direction, l.intensity, lux(1));
        }
        for (std::size_t i = 0; i < scene_.localLights.size(); ++i) {
            const LocalLight& l = scene_.localLights[i];
            // F2's lights do not fall off (unless faded); glTF's fall off as
            // 1/d²: candela = π·I·D², with D the light's distance to the
            // scene's centre, gives lux(I) there.
            const float distance = std::max(length(l.position - centre_), size_ * 1e-3f);
            const float candela = lux(1) * distance * distance;  // per unit of F2's intensity
            json light = {{"intensity", number(candela * l.intensity)}};
            const bool spot = l.kind == LocalLightKind::Spot;
            light["type"] = spot ? "spot" : "point";
            if (spot) {
                const double half = kPi / 2, degree = kPi / 180;
                const double outer = std::clamp(double(l.falloff) * degree, 1e-4, half);
                const double inner = std::clamp(double(l.radius) * degree, 0.0, outer * 0.999);
                light["spot"] = {{"innerConeAngle", number(float(inner))},
                                 {"outerConeAngle", number(float(outer))}};
            }
            lightNode(lightName(l.motion, spot ? "spot_light" : "point_light", i), std::move(light), l.motion,
                      l.position, spot ? l.direction : Vec3{}, l.intensity, candela);
        }
    }

    // ---- 5. animation -----------------------------------------------------------

    int timeAccessor(const std::vector<double>& frames) {
        std::vector<float> seconds;
        for (double f : frames) seconds.push_back(float(f / scene_.fps));
        if (auto found = timeAccessor_.find(seconds); found != timeAccessor_.end()) return found->second;
        const int accessor = buffer_.floats(seconds, "SCALAR", 1, 0, true);
        return timeAccessor_[seconds] = accessor;
    }

    void channel(int node, const char* path, const std::vector<double>& times,
                 const std::vector<float>& values, const char* type, int components, bool step) {
        channel(json{{"node", node}, {"path", path}}, times, values, type, components, step);
    }
    void channel(json target, const std::vector<double>& times, const std::vector<float>& values,
                 const char* type, int components, bool step) {
        samplers_.push_back({{"input", timeAccessor(times)},
                             {"output", buffer_.floats(values, type, components, 0, false)},
                             {"interpolation", step ? "STEP" : "LINEAR"}});
        channels_.push_back({{"sampler", samplers_.size() - 1}, {"target", std::move(target)}});
    }
    /// A channel of KHR_animation_pointer: `pointer` is a JSON pointer into the file.
    void pointerChannel(const std::string& pointer, const std::vector<float>& values, const char* type,
                        int components, bool step) {
        channel(
            json{{"path", "pointer"}, {"extensions", {{"KHR_animation_pointer", {{"pointer", pointer}}}}}},
            frames_, values, type, components, step);
        pointerUsed_ = true;
    }

    /// Visibility (SPEC 10.7) as the scale of the shapes' nodes: 0 while hidden, STEP.
    void visibility() {
        if (scene_.visibilityTracks.empty()) return;
        std::vector<std::vector<std::uint8_t>> reached(scene_.objects.size());
        std::vector<double> times{0};
        for (const TargetTrack& v : scene_.visibilityTracks) {
            for (const Key& k : v.track.keys) times.push_back(k.time);
            auto& shapes = reached[v.target.object];
            shapes.resize(shapeNode_[v.target.object].size(), 0);
            forEachShapeOf(scene_, v.target, v.shape,
                           [&](std::size_t shape, const ModelShape*) { shapes[shape] = 1; });
        }
        times = tidy(std::move(times), last_);
        std::vector<std::vector<std::uint8_t>> hidden(times.size());
        for (std::size_t j = 0; j < times.size(); ++j) {
            hidden[j].assign(nodes_.size(), 0);
            forEachHiddenShape(scene_, times[j], [&](std::size_t object, std::size_t shape) {
                hidden[j][std::size_t(shapeNode_[object][shape])] = 1;
            });
        }
        for (std::size_t i = 0; i < reached.size(); ++i) {
            for (std::size_t k = 0; k < reached[i].size(); ++k) {
                if (!reached[i][k]) continue;
                const std::size_t node = std::size_t(shapeNode_[i][k]);
                std::vector<float> scale;
                bool changes = false;
                for (std::size_t j = 0; j < times.size(); ++j) {
                    const float s = hidden[j][node] ? 0.0f : 1.0f;
                    changes = changes || hidden[j][node] != hidden[0][node];
                    scale.insert(scale.end(), {s, s, s});
                }
                if (hidden[0][node]) nodes_[node]["scale"] = numbers({0, 0, 0});
                if (changes) channel(int(node), "scale", times, scale, "VEC3", 3, true);
            }
        }
    }

    struct Sample {
        double time;
        GltfPose pose;
    };

    /// Whether LINEAR interpolation from `a` to `b` (lerp, slerp) passes
    /// within a ten-thousandth of the scene's size and a quarter degree of
    /// `mid`, turning at most 90° (near 180° the short way is a toss-up).
    bool linearEnough(const GltfPose& a, const GltfPose& b, const GltfPose& mid) const {
        float gap = 0;
        for (int c = 0; c < 3; ++c) {
            const float between = (a.translation[std::size_t(c)] + b.translation[std::size_t(c)]) / 2;
            gap = std::max(gap, std::fabs(mid.translation[std::size_t(c)] - between));
        }
        // slerp halfway is the normalised sum (b already on a's side: continuousQuaternion).
        double sum[4], norm = 0, dot = 0, ends = 0;
        for (std::size_t c = 0; c < 4; ++c) ends += double(a.rotation[c]) * b.rotation[c];
        if (ends < std::cos(kPi / 4)) return false;  // a quaternion holds half the angle
        for (std::size_t c = 0; c < 4; ++c) {
            sum[c] = double(a.rotation[c]) + b.rotation[c];
            norm += sum[c] * sum[c];
        }
        for (std::size_t c = 0; c < 4; ++c) dot += sum[c] * mid.rotation[c];
        const double cosQuarterDegree = std::cos(0.25 * kPi / 180 / 2);  // a quaternion holds half the angle
        return gap <= size_ * 1e-4f && norm > 0 && std::fabs(dot) / std::sqrt(norm) >= cosQuarterDegree;
    }

    /// Samples between `a` and `b` (excluded) wherever LINEAR interpolation
    /// would stray from the motion: easings within a frame, and turns of 180°
    /// or more between two samples, which slerp would take the short way back.
    void split(const MovingNode& m, const Sample& a, const Sample& b, int depth, std::vector<Sample>& out) {
        constexpr int kMaxSplits = 5;  // at most 32 samples a frame
        if (depth >= kMaxSplits || b.time - a.time <= 4 * kJumpFrames) return;
        Sample mid{(a.time + b.time) / 2, gltfPoseOf(m.localAt((a.time + b.time) / 2))};
        mid.pose.rotation = continuousQuaternion(mid.pose.rotation, a.pose.rotation);
        Sample end = b;
        end.pose.rotation = continuousQuaternion(b.pose.rotation, a.pose.rotation);
        // A turn of 180° or more looks like a small one (or none) at the
        // ends: a midpoint off the short way shows it.
        if (linearEnough(a.pose, end.pose, mid.pose)) return;
        split(m, a, mid, depth + 1, out);
        out.push_back(mid);
        split(m, mid, end, depth + 1, out);
    }

    void animation() {
        for (const MovingNode& m : moving_) {
            std::vector<Sample> samples;
            for (double t : m.times) {
                const Sample next{t, gltfPoseOf(m.localAt(t))};
                if (!samples.empty() && !m.step) split(m, Sample(samples.back()), next, 0, samples);
                samples.push_back(next);
            }
            for (std::size_t j = 1; j < samples.size(); ++j)
                samples[j].pose.rotation =
                    continuousQuaternion(samples[j].pose.rotation, samples[j - 1].pose.rotation);
            std::vector<double> times;
            std::vector<float> translation, rotation;
            bool moves = false, turns = false;
            const GltfPose& first = samples.front().pose;
            for (const Sample& sample : samples) {
                times.push_back(sample.time);
                moves = moves || sample.pose.translation != first.translation;
                turns = turns || sample.pose.rotation != first.rotation;
                translation.insert(translation.end(), sample.pose.translation.begin(),
                                   sample.pose.translation.end());
                rotation.insert(rotation.end(), sample.pose.rotation.begin(), sample.pose.rotation.end());
            }
            setPose(m.node, m.localAt(m.times[0]));
            if (moves) channel(m.node, "translation", times, translation, "VEC3", 3, m.step);
            if (turns) channel(m.node, "rotation", times, rotation, "VEC4", 4, m.step);
        }
    }

    // ---- 6. colours, intensities and zoom (--gltf-pointer) ---------------------------

    /// The shapes a `colour` track reaches get a material of their own (before the objects' nodes).
    void markKeyedColours() {
        forEachKeyedColour(scene_, 0, [this](std::size_t object, std::size_t shape, Vec3) {
            keyedMaterial_.emplace(std::pair{object, shape}, -1);
        });
    }

    /// Every frame's value, as F2 computes it, through KHR_animation_pointer;
    /// a property that never changes gets no channel.
    void pointerChannels() {
        const auto changes = [](const std::vector<float>& v, std::size_t width) {
            for (std::size_t k = width; k < v.size(); ++k)
                if (v[k] != v[k % width]) return true;
            return false;
        };
        // Colours: the last track to reach a shape is its colour (forEachKeyedColour).
        std::map<std::pair<std::size_t, std::size_t>, std::vector<float>> colours;
        for (double f : frames_) {
            std::map<std::pair<std::size_t, std::size_t>, Vec3> at;
            forEachKeyedColour(scene_, f, [&](std::size_t object, std::size_t shape, Vec3 rgb) {
                at[{object, shape}] = rgb;
            });
            for (const auto& [shape, rgb] : at) {
                std::vector<float>& v = colours[shape];
                // Rounded as the renderer's colours are, then linear as baseColorFactor is.
                for (float c : {rgb.x, rgb.y, rgb.z})
                    v.push_back(linearFromSrgb(std::uint8_t(std::lround(c))));
                v.push_back(1.0f);
            }
        }
        for (const auto& [shape, values] : colours) {
            const int material = keyedMaterial_.at(shape);
            if (!materials_[std::size_t(material)]["pbrMetallicRoughness"].contains("baseColorFactor"))
                continue;
            if (changes(values, 4))
                pointerChannel(
                    "/materials/" + std::to_string(material) + "/pbrMetallicRoughness/baseColorFactor",
                    values, "VEC4", 4, false);
        }
        for (const PointerLight& l : pointerLights_) {
            const Track& track = scene_.lightMotions[std::size_t(l.motion)].intensity;
            std::vector<float> values;
            for (double f : frames_)
                values.push_back(l.factor * lightIntensityAt(scene_, l.motion, l.written, f));
            if (changes(values, 1))
                pointerChannel(
                    "/extensions/KHR_lights_punctual/lights/" + std::to_string(l.light) + "/intensity",
                    values, "SCALAR", 1, allSteps(track) && !track.drives);
        }
        const Track& zoom = scene_.camera.zoom;
        std::vector<float> yfov;
        const double w = options_.width, h = options_.height;
        for (double f : frames_)
            yfov.push_back(float(2.0 * std::atan(h / (2.0 * w * cameraDistanceAt(scene_, f)))));
        if (changes(yfov, 1))
            pointerChannel("/cameras/0/perspective/yfov", yfov, "SCALAR", 1, allSteps(zoom) && !zoom.drives);
    }

    // ---- what is left out ---------------------------------------------------------

    void warnings() {
        const char* without = " (--gltf-pointer exports them)";
        if (!scene_.colourTracks.empty() && !options_.pointer)
            warnings_.push_back(
                std::string("colour keys and drives not exported: the shapes keep their /paint "
                            "colour") +
                without);
        bool intensityKeys = false, ambientKeys = false;
        for (const LightMotion& l : scene_.lightMotions) {
            const bool keyed = !l.intensity.keys.empty() || l.intensity.drives;
            (l.ambient ? ambientKeys : intensityKeys) |= keyed;
        }
        if (intensityKeys && !options_.pointer)
            warnings_.push_back(
                std::string("light intensity keys and drives not exported: the lights keep their written "
                            "intensity") +
                without);
        if (ambientKeys)  // glTF has no ambient light: an extra of the scene
            warnings_.push_back(
                "ambient intensity keys and drives not exported: the scene's extras give the "
                "written ambient light");
        if ((!scene_.camera.zoom.keys.empty() || scene_.camera.zoom.drives) && !options_.pointer)
            warnings_.push_back(
                std::string("camera d keys and drives not exported: the camera keeps its field "
                            "of view at frame 0") +
                without);
        if (!scene_.captions.empty())
            warnings_.push_back(std::to_string(scene_.captions.size()) +
                                " caption(s) left out (captions are drawn by f2 only)");
    }

    GltfDocument finish() {
        // Children from parents, roots in node order.
        std::vector<json> children(nodes_.size(), json::array());
        json roots = json::array();
        for (std::size_t i = 0; i < nodes_.size(); ++i) {
            if (parentOf_[i] < 0)
                roots.push_back(i);
            else
                children[std::size_t(parentOf_[i])].push_back(i);
        }
        json nodes = json::array();
        for (std::size_t i = 0; i < nodes_.size(); ++i) {
            if (!children[i].empty()) nodes_[i]["children"] = std::move(children[i]);
            nodes.push_back(std::move(nodes_[i]));
        }
        json extras = {{"fps", scene_.fps},
                       {"lastFrame", last_},
                       {"ambient", number(ambientAt(scene_, 0))},
                       {"background", {scene_.background.r, scene_.background.g, scene_.background.b}}};
        json gltf = {
            {"asset", {{"version", "2.0"}, {"generator", "F2 Stage (f2 export --gltf)"}}},
            {"scene", 0},
            {"scenes", {{{"name", options_.source}, {"nodes", roots}, {"extras", {{"f2", extras}}}}}},
            {"nodes", std::move(nodes)},
            {"cameras", cameras_}};
        if (!meshes_.empty()) {
            gltf["meshes"] = meshes_;
            gltf["materials"] = materials_;
        }
        if (!textures_.empty()) {
            gltf["images"] = images_;
            gltf["textures"] = textures_;
            gltf["samplers"] = {
                {{"magFilter", kNearest}, {"minFilter", kNearest}, {"wrapS", kRepeat}, {"wrapT", kRepeat}}};
        }
        json used = json::array();
        if (!lights_.empty()) {
            gltf["extensions"]["KHR_lights_punctual"]["lights"] = lights_;
            used.push_back("KHR_lights_punctual");
        }
        if (emissiveStrength_) used.push_back("KHR_materials_emissive_strength");
        if (pointerUsed_) used.push_back("KHR_animation_pointer");
        if (!used.empty()) gltf["extensionsUsed"] = used;
        if (!channels_.empty())
            gltf["animations"] = {{{"name", "f2"}, {"samplers", samplers_}, {"channels", channels_}}};
        GltfDocument out;
        out.bin = std::move(buffer_.bytes);
        out.bin.resize((out.bin.size() + 3) & ~std::size_t(3), 0);
        if (!out.bin.empty()) {
            json b = {{"byteLength", out.bin.size()}};
            if (!options_.bufferUri.empty()) b["uri"] = options_.bufferUri;
            gltf["buffers"] = {b};
            gltf["bufferViews"] = buffer_.views;
            gltf["accessors"] = buffer_.accessors;
        }
        out.nodes = nodes_.size();
        out.meshes = meshes_.size();
        out.materials = materials_.size();
        out.channels = channels_.size();
        // Names are F2's (ASCII), but the scene's file name may be any bytes:
        // bytes that are not UTF-8 become U+FFFD, quotes and controls are escaped.
        out.json = gltf.dump(-1, ' ', false, json::error_handler_t::replace);
        out.warnings = std::move(warnings_);
        return out;
    }
};

void appendWord(std::string& out, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) out.push_back(char((value >> (8 * i)) & 0xff));  // little-endian
}
}  // namespace

GltfDocument gltfScene(const SceneDesc& scene, const GltfOptions& options) {
    return GltfBuilder(scene, options).build();
}

std::string uriOfFileName(std::string_view name) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    for (const char c : name) {
        const auto byte = static_cast<unsigned char>(c);
        if (std::isalnum(byte) || c == '-' || c == '.' || c == '_' || c == '~') {
            out += c;
        } else {
            out += '%';
            out += kHex[byte >> 4];
            out += kHex[byte & 15];
        }
    }
    return out;
}

std::string glbBytes(const GltfDocument& document) {
    std::string json = document.json;
    json.resize((json.size() + 3) & ~std::size_t(3), ' ');  // chunks are 4-aligned; JSON pads with spaces
    const std::size_t total = 12 + 8 + json.size() + (document.bin.empty() ? 0 : 8 + document.bin.size());
    std::string out;
    out.reserve(total);
    out += "glTF";
    appendWord(out, 2);
    appendWord(out, std::uint32_t(total));
    appendWord(out, std::uint32_t(json.size()));
    out += "JSON";
    out += json;
    if (!document.bin.empty()) {
        appendWord(out, std::uint32_t(document.bin.size()));
        out.append("BIN\0", 4);
        out.append(reinterpret_cast<const char*>(document.bin.data()), document.bin.size());
    }
    return out;
}

}  // namespace f2
