// glTF export: F2's left-handed frame mirrored into glTF's (io/gltf_frame),
// the tessellated primitives (io/tessellate), and the document's node tree,
// samplers and camera (io/gltf_export).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <vector>

#include "core/anim/camera_motion.h"
#include "io/gltf_export.h"
#include "io/gltf_frame.h"
#include "io/tessellate.h"
#include "test_scenes.h"

namespace f2 {
namespace {

using json = nlohmann::json;

/// q·v·q* for a unit quaternion (x, y, z, w).
Vec3 rotate(const std::array<float, 4>& q, Vec3 v) {
    const Vec3 u{q[0], q[1], q[2]};
    const float w = q[3];
    return u * (2 * dot(u, v)) + v * (w * w - dot(u, u)) + cross(u, v) * (2 * w);
}

// --- The frame -----------------------------------------------------------------

TEST(GltfFrame, QuaternionOfSingleTurns) {
    const float h = std::sqrt(0.5f);
    const auto id = quaternionOf(Mat3{});
    EXPECT_FLOAT_EQ(id[3], 1);
    // Ry(90) turns +z toward +x: about +y by +90° in the right-hand rule's sense.
    const auto y90 = quaternionOf(rotationFromEulerDegrees(0, 90, 0));
    EXPECT_NEAR(y90[1], h, 1e-6);
    EXPECT_NEAR(y90[3], h, 1e-6);
    // A half turn (trace -1): the branch without w.
    const auto x180 = quaternionOf(rotationFromEulerDegrees(180, 0, 0));
    EXPECT_NEAR(std::fabs(x180[0]), 1, 1e-6);
}

TEST(GltfFrame, MirrorReversesTurnsAboutXAndYKeepsZ) {
    const float h = std::sqrt(0.5f);
    // Mirroring z: a turn about y or x goes the other way, one about z stays.
    const GltfPose y = gltfPoseOf(Transform::fromPose({1, 2, 3}, {0, 90, 0}));
    EXPECT_NEAR(y.rotation[1], -h, 1e-6);
    EXPECT_NEAR(y.rotation[3], h, 1e-6);
    EXPECT_EQ(y.translation, (std::array<float, 3>{1, 2, -3}));
    const GltfPose z = gltfPoseOf(Transform::fromPose({}, {0, 0, 90}));
    EXPECT_NEAR(z.rotation[2], h, 1e-6);
    EXPECT_NEAR(z.rotation[3], h, 1e-6);
}

TEST(GltfFrame, EveryTransformCommutesWithTheMirror) {
    // For any pose T and point p: the glTF node maps S·p to S·(T·p).
    std::mt19937 random(test::testSeed(26));
    std::uniform_real_distribution<float> angle(-180, 180), coordinate(-100, 100);
    for (int i = 0; i < 200; ++i) {
        const Transform t = Transform::fromPose({coordinate(random), coordinate(random), coordinate(random)},
                                                {angle(random), angle(random), angle(random)});
        const GltfPose pose = gltfPoseOf(t);
        const float norm = std::hypot(std::hypot(pose.rotation[0], pose.rotation[1]),
                                      std::hypot(pose.rotation[2], pose.rotation[3]));
        EXPECT_NEAR(norm, 1, 1e-6);
        const Vec3 p{coordinate(random), coordinate(random), coordinate(random)};
        const Vec3 translation{pose.translation[0], pose.translation[1], pose.translation[2]};
        EXPECT_VEC_NEAR(rotate(pose.rotation, gltfFromF2(p)) + translation, gltfFromF2(t.applyToPoint(p)),
                        1e-3f);
    }
}

TEST(GltfFrame, AModelFacingTheF2CameraFacesTheGltfCamera) {
    // F2: the default camera at z = -500 looks along +z; a robot turned by
    // ry = 180 faces -z, toward it. glTF: the camera looks down its -Z and the
    // robot's front (F2's local +z) is its local -Z.
    const GltfPose camera = gltfPoseOf(Transform::fromPose({0, 0, -500}, {}));
    const GltfPose robot = gltfPoseOf(Transform::fromPose({}, {0, 180, 0}));
    const Vec3 eye{camera.translation[0], camera.translation[1], camera.translation[2]};
    const Vec3 looks = rotate(camera.rotation, {0, 0, -1});
    const Vec3 faces = rotate(robot.rotation, gltfFromF2({0, 0, 1}));
    EXPECT_VEC_NEAR(eye, Vec3(0, 0, 500), 1e-4f);
    EXPECT_VEC_NEAR(looks, Vec3(0, 0, -1), 1e-6f);  // toward the robot at the origin
    EXPECT_VEC_NEAR(faces, Vec3(0, 0, 1), 1e-6f);   // toward the camera
}

TEST(GltfFrame, ContinuousQuaternionTakesTheNearSign) {
    const std::array<float, 4> q{0, 0.6f, 0, -0.8f}, previous{0, 0, 0, 1};
    EXPECT_EQ(continuousQuaternion(q, previous), (std::array<float, 4>{-0.0f, -0.6f, -0.0f, 0.8f}));
    EXPECT_EQ(continuousQuaternion(previous, previous), previous);
}

// --- Tessellation ----------------------------------------------------------------

/// Checks what every mesh must be: indices in range, unit normals, no
/// degenerate triangle, each triangle facing the way its normals do.
void expectWellFormed(const TriangleMesh& mesh) {
    ASSERT_EQ(mesh.positions.size(), mesh.normals.size());
    ASSERT_EQ(mesh.indices.size() % 3, 0u);
    for (const Vec3& n : mesh.normals) EXPECT_NEAR(length(n), 1, 1e-6);
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        for (int k = 0; k < 3; ++k) ASSERT_LT(mesh.indices[t + std::size_t(k)], mesh.positions.size());
        const Vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                   c = mesh.positions[mesh.indices[t + 2]];
        const Vec3 area = cross(b - a, c - a);
        EXPECT_GT(length(area), 0) << "triangle " << t / 3;
        const Vec3 normals = mesh.normals[mesh.indices[t]] + mesh.normals[mesh.indices[t + 1]] +
                             mesh.normals[mesh.indices[t + 2]];
        EXPECT_GT(dot(area, normals), 0) << "triangle " << t / 3 << " faces inward";
    }
}

TEST(Tessellate, SphereVerticesOnTheSphereWithRadialNormals) {
    for (int n : {3, 8, 32, 101}) {
        SCOPED_TRACE(n);
        const float r = 6.5f;
        const TriangleMesh mesh = tessellate(ShapeKind::Sphere, {r, 0, 0}, n);
        const std::size_t stacks = std::size_t(std::max(2, n / 2)), slices = std::size_t(n);
        EXPECT_EQ(mesh.positions.size(), (stacks + 1) * (slices + 1));
        EXPECT_EQ(mesh.indices.size(), 3 * 2 * slices * (stacks - 1));  // one triangle per quad at the poles
        expectWellFormed(mesh);
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            EXPECT_NEAR(length(mesh.positions[v]), r, r * 1e-6);
            EXPECT_VEC_NEAR(mesh.normals[v], mesh.positions[v] / r, 1e-6f);
        }
    }
}

TEST(Tessellate, CylinderVerticesOnTheSideOrTheCaps) {
    for (int n : {3, 32}) {
        SCOPED_TRACE(n);
        const float r = 10, h = 100;
        const TriangleMesh mesh = tessellate(ShapeKind::Cylinder, {r, h, 0}, n);
        const std::size_t s = std::size_t(n);
        EXPECT_EQ(mesh.positions.size(), 2 * (s + 1) + 2 * (s + 2));
        EXPECT_EQ(mesh.indices.size(), 3 * 4 * s);
        expectWellFormed(mesh);
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            const Vec3 p = mesh.positions[v], normal = mesh.normals[v];
            const float radial = std::hypot(p.x, p.z);
            if (normal.y == 0) {  // the side: on the radius, normal outward
                EXPECT_NEAR(radial, r, r * 1e-6);
                EXPECT_LE(std::fabs(p.y), h / 2);
                EXPECT_VEC_NEAR(normal, Vec3(p.x / r, 0, p.z / r), 1e-6f);
            } else {  // a cap: on its plane, inside the radius, normal along the axis
                EXPECT_EQ(std::fabs(p.y), h / 2);
                EXPECT_LE(radial, r * (1 + 1e-6f));
                EXPECT_EQ(normal.y, p.y > 0 ? 1.0f : -1.0f);
            }
        }
    }
}

TEST(Tessellate, BoxIsSixFacesOnItsSides) {
    const Vec3 size{60, 50, 40};
    const TriangleMesh mesh = tessellate(ShapeKind::Box, size, 32);
    EXPECT_EQ(mesh.positions.size(), 24u);
    EXPECT_EQ(mesh.indices.size(), 36u);
    expectWellFormed(mesh);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const Vec3 p = mesh.positions[v], normal = mesh.normals[v];
        for (int a = 0; a < 3; ++a) {
            EXPECT_EQ(std::fabs(p[a]), size[a] / 2);  // a corner
            if (normal[a] != 0) {
                EXPECT_EQ(p[a] * normal[a], size[a] / 2);  // on the face its normal names
            }
        }
    }
}

// --- The document ----------------------------------------------------------------

json exported(const SceneDesc& scene, GltfDocument* document = nullptr, bool pointer = false) {
    GltfOptions options;
    options.pointer = pointer;
    options.width = scene.camera.width;
    options.height = scene.camera.height;
    GltfDocument doc = gltfScene(scene, options);
    json out = json::parse(doc.json);
    if (document) *document = std::move(doc);
    return out;
}

int nodeNamed(const json& gltf, const std::string& name) {
    for (std::size_t i = 0; i < gltf["nodes"].size(); ++i)
        if (gltf["nodes"][i]["name"] == name) return int(i);
    ADD_FAILURE() << "no node " << name;
    return -1;
}

int parentOf(const json& gltf, int node) {
    for (std::size_t i = 0; i < gltf["nodes"].size(); ++i)
        for (const json& c : gltf["nodes"][i].value("children", json::array()))
            if (c == node) return int(i);
    return -1;
}

/// The channels of node `node` as path -> sampler.
std::map<std::string, json> channelsOf(const json& gltf, int node) {
    std::map<std::string, json> out;
    if (!gltf.contains("animations")) return out;
    const json& animation = gltf["animations"][0];
    for (const json& c : animation["channels"])
        if (c["target"]["node"] == node)
            out[c["target"]["path"]] = animation["samplers"][c["sampler"].get<int>()];
    return out;
}

TEST(GltfExport, NodeTreeOfAModelAndItsRides) {
    const SceneDesc scene = test::sceneFromText(
        "/camera 400 300 0.5 0 0 -500\n"
        "/robot r 0 0 0\n"
        "/sphere ball 10 0 40 0\n"
        "/attach ball r.lhand\n"
        "/box crate 20 20 20 100 0 0\n"
        "/attach crate r at 12\n"
        "/key 0 r.head 0 0 0 0 0 0\n"
        "/key 24 r.head 0 0 0 0 90 0\n");
    const json gltf = exported(scene);
    const int robot = nodeNamed(gltf, "r"), lhand = nodeNamed(gltf, "r.lhand");
    const int lhandPose = nodeNamed(gltf, "r.lhand.pose"), body = nodeNamed(gltf, "r.body.pose");
    EXPECT_EQ(parentOf(gltf, robot), -1);
    EXPECT_EQ(parentOf(gltf, nodeNamed(gltf, "r.body")), robot);
    EXPECT_EQ(parentOf(gltf, lhand), body);
    EXPECT_EQ(parentOf(gltf, lhandPose), lhand);
    // The pivot is the part's node's translation: robot lhand (-52, 140, 0).
    EXPECT_EQ(gltf["nodes"][lhand]["translation"], json::parse("[-52.0, 140.0, 0.0]"));
    // A ride that never changes is parenting; one that does is baked at the top.
    EXPECT_EQ(parentOf(gltf, nodeNamed(gltf, "ball")), lhandPose);
    const int crate = nodeNamed(gltf, "crate");
    EXPECT_EQ(parentOf(gltf, crate), -1);
    // The head turns: a rotation channel sampled at every frame 0..24, in seconds.
    const auto head = channelsOf(gltf, nodeNamed(gltf, "r.head.pose"));
    ASSERT_TRUE(head.count("rotation"));
    EXPECT_EQ(head.at("rotation")["interpolation"], "LINEAR");
    const json& times = gltf["accessors"][head.at("rotation")["input"].get<int>()];
    EXPECT_EQ(times["count"], 25);
    EXPECT_NEAR(times["max"][0].get<double>(), 1.0, 1e-7);
    // Every shape is a node with a mesh, named as the language names it; a
    // primitive's is `name.shape`, so that no two nodes share a name.
    EXPECT_TRUE(gltf["nodes"][nodeNamed(gltf, "r.head.leye")].contains("mesh"));
    EXPECT_EQ(gltf["nodes"][nodeNamed(gltf, "ball.shape")]["extras"]["f2Shape"], "ball");
    std::set<std::string> names;
    for (const json& node : gltf["nodes"]) EXPECT_TRUE(names.insert(node["name"]).second) << node["name"];
}

TEST(GltfExport, StepKeysAreStepAndVisibilityIsScale) {
    const SceneDesc scene = test::sceneFromText(
        "/sphere a 10 0 0 0\n"
        "/key 0 a 0 0 0 0 0 0 step\n"
        "/key 10 a 100 0 0 0 0 0 step\n"
        "/key 20 a 200 0 0 0 0 0\n"
        "/key 5 a visible 0\n"
        "/key 15 a visible 1\n");
    const json gltf = exported(scene);
    const int a = nodeNamed(gltf, "a");
    const auto moves = channelsOf(gltf, a);
    ASSERT_TRUE(moves.count("translation"));
    EXPECT_EQ(moves.at("translation")["interpolation"], "STEP");
    EXPECT_EQ(gltf["accessors"][moves.at("translation")["input"].get<int>()]["count"], 3);  // the keys
    const int shape = gltf["nodes"][a]["children"][0];
    const auto shown = channelsOf(gltf, shape);
    ASSERT_TRUE(shown.count("scale"));
    EXPECT_EQ(shown.at("scale")["interpolation"], "STEP");
}

TEST(GltfExport, TurnsOfHalfATurnOrMoreBetweenFramesAreSplit) {
    // 360° a frame: every frame's sample is the same rotation, so without
    // samples between the frames the box would not turn at all.
    const SceneDesc scene = test::sceneFromText(
        "/box b 10 10 10 0 0 0\n"
        "/key 0 b 0 0 0 0 0 0\n"
        "/key 2 b 0 0 0 0 720 0\n");
    GltfDocument document;
    const json gltf = exported(scene, &document);
    const auto turns = channelsOf(gltf, nodeNamed(gltf, "b"));
    ASSERT_TRUE(turns.count("rotation"));
    const json& output = gltf["accessors"][turns.at("rotation")["output"].get<int>()];
    const std::size_t count = output["count"];
    EXPECT_GE(count, 2u * 4 + 1);  // at least four samples a frame
    std::vector<float> q(4 * count);
    const std::size_t offset = gltf["bufferViews"][output["bufferView"].get<int>()]["byteOffset"];
    std::memcpy(q.data(), document.bin.data() + offset, q.size() * sizeof(float));
    // Consecutive samples at most a quarter turn apart (q1·q2 >= cos 45°), the
    // sign continuous: slerp turns the right way.
    for (std::size_t i = 1; i < count; ++i) {
        const float d = q[4 * i] * q[4 * i - 4] + q[4 * i + 1] * q[4 * i - 3] + q[4 * i + 2] * q[4 * i - 2] +
                        q[4 * i + 3] * q[4 * i - 1];
        EXPECT_GE(d, std::cos(kPi / 4) - 1e-6) << "sample " << i;
    }
}

TEST(GltfExport, CameraFieldOfViewAndGlbLayout) {
    const SceneDesc scene = test::sceneFromText("/camera 800 400 1\n/sphere s 10 0 0 100\n");
    GltfDocument document;
    const json gltf = exported(scene, &document);
    const json& perspective = gltf["cameras"][0]["perspective"];
    EXPECT_NEAR(perspective["aspectRatio"].get<double>(), 2.0, 1e-6);
    // The screen is 1 wide and h/w = 0.5 high at d = 1: yfov = 2·atan(0.25).
    EXPECT_NEAR(perspective["yfov"].get<double>(), 2 * std::atan(0.25), 1e-6);
    EXPECT_FALSE(gltf.contains("animations"));  // nothing moves
    const std::string glb = glbBytes(document);
    ASSERT_GE(glb.size(), 28u);
    EXPECT_EQ(glb.substr(0, 4), "glTF");
    std::uint32_t words[5];
    std::memcpy(words, glb.data() + 4, sizeof words);
    EXPECT_EQ(words[0], 2u);          // version
    EXPECT_EQ(words[1], glb.size());  // total length
    EXPECT_EQ(words[2] % 4, 0u);      // the JSON chunk, padded
    EXPECT_EQ(glb.substr(16, 4), "JSON");
    EXPECT_EQ(glb.size(), 12 + 8 + words[2] + 8 + document.bin.size());
}

TEST(GltfExport, LightsPointTheirMinusZAlongTheirDirection) {
    // A sun shining straight down along +x (F2 and glTF agree on x and y) and
    // a spot light at (0, 300, 0) shining down, its cone 18° to 30°; one sphere
    // of radius 10 at the origin, so the scene's centre is the origin.
    const SceneDesc scene = test::sceneFromText(
        "/dir_light 0.5 1 0 0\n"
        "/spot_light 0.8 0 300 0 0 -1 0 18 30\n"
        "/sphere s 10 0 0 0\n");
    const json gltf = exported(scene);
    const json& lights = gltf["extensions"]["KHR_lights_punctual"]["lights"];
    ASSERT_EQ(lights.size(), 2u);
    EXPECT_NEAR(lights[0]["intensity"].get<double>(), kPi * 0.5, 1e-5);  // lux = π·I
    EXPECT_EQ(lights[1]["type"], "spot");
    EXPECT_NEAR(lights[1]["intensity"].get<double>(), kPi * 0.8 * 300 * 300, 1);  // candela = π·I·D²
    EXPECT_NEAR(lights[1]["spot"]["innerConeAngle"].get<double>(), 18 * kPi / 180, 1e-6);
    EXPECT_NEAR(lights[1]["spot"]["outerConeAngle"].get<double>(), 30 * kPi / 180, 1e-6);
    const auto direction = [&](const std::string& name) {
        const json& node = gltf["nodes"][nodeNamed(gltf, name)];
        const json r = node.value("rotation", json::parse("[0, 0, 0, 1]"));
        return rotate({r[0].get<float>(), r[1].get<float>(), r[2].get<float>(), r[3].get<float>()},
                      {0, 0, -1});
    };
    EXPECT_VEC_NEAR(direction("dir_light 1"), Vec3(1, 0, 0), 1e-6f);
    EXPECT_VEC_NEAR(direction("spot_light 1"), Vec3(0, -1, 0), 1e-6f);
    EXPECT_EQ(gltf["nodes"][nodeNamed(gltf, "spot_light 1")]["translation"],
              json::parse("[0.0, 300.0, 0.0]"));
}

/// Accessor `index`'s floats, from the document's buffer.
std::vector<float> floatsOf(const json& gltf, const GltfDocument& document, int index) {
    const json& accessor = gltf["accessors"][index];
    const std::string type = accessor["type"];
    const std::size_t components = type == "VEC2" ? 2 : type == "VEC3" ? 3 : type == "VEC4" ? 4 : 1;
    std::vector<float> out(components * accessor["count"].get<std::size_t>());
    const std::size_t offset = gltf["bufferViews"][accessor["bufferView"].get<int>()]["byteOffset"];
    std::memcpy(out.data(), document.bin.data() + offset, out.size() * sizeof(float));
    return out;
}

TEST(GltfExport, ABoxCheckerIsATextureWithF2sCells) {
    // At points all over the faces of a box whose sides are no multiples of
    // the cell (and one that is: 120 = 4 x 30, its z faces on cell planes), the
    // texel the texture coordinates pick has the colour F2's 3D checker gives
    // there (docs/rendering.md): the /paint colour where floor(x/s) +
    // floor(y/s) + floor(z/s) is even, read just inside the surface.
    const SceneDesc scene = test::sceneFromText(
        "/box b 130 70 120 10 20 30 0 30 0\n"
        "/paint b 200 10 10\n"
        "/checker b 10 10 200 30\n");
    GltfDocument document;
    const json gltf = exported(scene, &document);
    ASSERT_EQ(gltf["textures"].size(), 1u);
    const json& primitive = gltf["meshes"][0]["primitives"][0];
    const std::vector<float> position = floatsOf(gltf, document, primitive["attributes"]["POSITION"]);
    const std::vector<float> normal = floatsOf(gltf, document, primitive["attributes"]["NORMAL"]);
    const std::vector<float> uv = floatsOf(gltf, document, primitive["attributes"]["TEXCOORD_0"]);
    const float s = 30;
    std::mt19937 random(test::testSeed(30));
    std::uniform_real_distribution<float> unit(0, 1);
    int checked = 0;
    for (std::size_t face = 0; face < 6; ++face) {
        // A face's four vertices (tessellate's order): (-,-), (+,-), (+,+), (-,+) in its (u, v).
        const std::size_t v0 = 4 * face;
        for (int k = 0; k < 200; ++k) {
            const float a = unit(random), b = unit(random);
            const auto mix = [&](const std::vector<float>& data, std::size_t n, std::size_t c) {
                const auto at = [&](std::size_t v) { return data[(v0 + v) * n + c]; };
                return (1 - a) * (1 - b) * at(0) + a * (1 - b) * at(1) + a * b * at(2) + (1 - a) * b * at(3);
            };
            // Back in F2's frame (z mirrored), just inside the face.
            const Vec3 n{normal[3 * v0], normal[3 * v0 + 1], -normal[3 * v0 + 2]};
            const Vec3 p = Vec3{mix(position, 3, 0), mix(position, 3, 1), -mix(position, 3, 2)} - n * 1e-3f;
            const int cells = int(std::floor(p.x / s) + std::floor(p.y / s) + std::floor(p.z / s));
            const int texel = int(std::floor(2 * mix(uv, 2, 0))) + int(std::floor(2 * mix(uv, 2, 1)));
            EXPECT_EQ(((cells % 2) + 2) % 2, ((texel % 2) + 2) % 2)
                << "face " << face << " at " << p << " (texel " << texel << ")";
            ++checked;
        }
    }
    EXPECT_EQ(checked, 1200);
}

TEST(GltfExport, ColourIntensityAndZoomKeysThroughAnimationPointer) {
    // --gltf-pointer (issue 26): each keyed property a channel of
    // KHR_animation_pointer with F2's value at every frame; without it,
    // no such channel and a warning for each.
    const SceneDesc scene = test::sceneFromText(
        "/camera 400 300 1 0 0 -500\n"
        "/point_light 1 0 100 -100 name lamp\n"
        "/sphere ball 10 0 0 0\n"
        "/sphere other 10 50 0 0\n"
        "/key 0 ball colour 255 0 0\n"
        "/key 10 ball colour 0 0 255\n"
        "/key 0 lamp intensity 1\n"
        "/key 10 lamp intensity 0.2\n"
        "/key 0 camera d 1\n"
        "/key 10 camera d 2 ease\n");
    GltfDocument document;
    const json gltf = exported(scene, &document, true);
    EXPECT_TRUE(document.warnings.empty()) << document.warnings.front();
    EXPECT_NE(
        std::find(gltf["extensionsUsed"].begin(), gltf["extensionsUsed"].end(), "KHR_animation_pointer"),
        gltf["extensionsUsed"].end());
    std::map<std::string, std::vector<float>> byPointer;
    const json& animation = gltf["animations"][0];
    for (const json& c : animation["channels"]) {
        if (c["target"]["path"] != "pointer") continue;
        const json& sampler = animation["samplers"][c["sampler"].get<int>()];
        byPointer[c["target"]["extensions"]["KHR_animation_pointer"]["pointer"]] =
            floatsOf(gltf, document, sampler["output"].get<int>());
    }
    ASSERT_EQ(byPointer.size(), 3u);
    // The ball's colour, on a material of its own (the other sphere keeps the shared one).
    const int ballMaterial = gltf["meshes"][gltf["nodes"][nodeNamed(gltf, "ball.shape")]["mesh"].get<int>()]
                                 ["primitives"][0]["material"];
    const int otherMaterial = gltf["meshes"][gltf["nodes"][nodeNamed(gltf, "other.shape")]["mesh"].get<int>()]
                                  ["primitives"][0]["material"];
    EXPECT_NE(ballMaterial, otherMaterial);
    const auto& colour =
        byPointer.at("/materials/" + std::to_string(ballMaterial) + "/pbrMetallicRoughness/baseColorFactor");
    ASSERT_EQ(colour.size(), 4u * 11);
    EXPECT_EQ(std::vector<float>(colour.begin(), colour.begin() + 4), (std::vector<float>{1, 0, 0, 1}));
    EXPECT_EQ(std::vector<float>(colour.end() - 4, colour.end()), (std::vector<float>{0, 0, 1, 1}));
    EXPECT_EQ(colour[20], colour[22]);  // frame 5: halfway, as much red as blue
    EXPECT_GT(colour[20], 0.0f);
    EXPECT_LT(colour[20], 1.0f);
    // The lamp: the light's own intensity at frame 0, a fifth of it at frame 10.
    const auto& intensity = byPointer.at("/extensions/KHR_lights_punctual/lights/0/intensity");
    ASSERT_EQ(intensity.size(), 11u);
    EXPECT_FLOAT_EQ(intensity[0],
                    gltf["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"].get<float>());
    EXPECT_FLOAT_EQ(intensity[10], 0.2f * intensity[0]);
    // The field of view from d at every frame, eased as F2 eases it.
    const auto& yfov = byPointer.at("/cameras/0/perspective/yfov");
    ASSERT_EQ(yfov.size(), 11u);
    for (int f = 0; f <= 10; ++f)
        EXPECT_EQ(yfov[std::size_t(f)],
                  float(2.0 * std::atan(300.0 / (2.0 * 400.0 * cameraDistanceAt(scene, f)))))
            << "frame " << f;

    const json plain = exported(scene, &document, false);
    EXPECT_FALSE(plain.contains("animations"));  // nothing here moves but what the pointer carries
    EXPECT_EQ(document.warnings.size(), 3u);
}

TEST(GltfExport, ACheckeredSphereIsSplitByCell) {
    // A curved shape's checker (issue 26): its triangles in two primitives,
    // those whose centre is in an even cell of F2's checker (docs/rendering.md,
    // the shape's own frame) in the paint's material, the others in the
    // checker colour's; the two together are every triangle of the sphere.
    const SceneDesc scene = test::sceneFromText(
        "/camera 400 300 1 0 0 -500\n"
        "/sphere ball 50 0 0 0 0 30 0\n"
        "/paint ball 255 0 0\n"
        "/checker ball 0 0 255 20\n");
    GltfDocument document;
    const json gltf = exported(scene, &document);
    EXPECT_TRUE(document.warnings.empty());
    const json& mesh = gltf["meshes"][gltf["nodes"][nodeNamed(gltf, "ball.shape")]["mesh"].get<int>()];
    ASSERT_EQ(mesh["primitives"].size(), 2u);
    const std::vector<float> positions =
        floatsOf(gltf, document, mesh["primitives"][0]["attributes"]["POSITION"].get<int>());
    std::size_t triangles = 0;
    for (int k = 0; k < 2; ++k) {
        const json& primitive = mesh["primitives"][k];
        const json& material = gltf["materials"][primitive["material"].get<int>()];
        EXPECT_EQ(material["pbrMetallicRoughness"]["baseColorFactor"],
                  k == 0 ? json::parse("[1.0, 0.0, 0.0, 1.0]") : json::parse("[0.0, 0.0, 1.0, 1.0]"));
        const json& accessor = gltf["accessors"][primitive["indices"].get<int>()];
        const std::size_t count = accessor["count"],
                          offset = gltf["bufferViews"][accessor["bufferView"].get<int>()]["byteOffset"];
        ASSERT_EQ(accessor["componentType"], 5123);  // unsigned short: few vertices
        std::vector<std::uint16_t> indices(count);
        std::memcpy(indices.data(), document.bin.data() + offset, count * 2);
        for (std::size_t t = 0; t < count; t += 3) {
            // Back in F2's frame (z mirrored) and the shape's own: the cell of the triangle's centre.
            Vec3 centre{};
            for (std::size_t v = 0; v < 3; ++v) {
                const float* p = &positions[3 * indices[t + v]];
                centre = centre + Vec3{p[0], p[1], -p[2]} / 3.0f;
            }
            const int cells =
                int(std::floor(centre.x / 20) + std::floor(centre.y / 20) + std::floor(centre.z / 20));
            EXPECT_EQ(((cells % 2) + 2) % 2, k) << "triangle " << t / 3 << " of primitive " << k;
        }
        triangles += count / 3;
    }
    EXPECT_EQ(triangles,
              tessellate(ShapeKind::Sphere, {50, 0, 0}, GltfOptions{}.tessellation).indices.size() / 3);
}

TEST(GltfExport, AnyFileNameIsEscapedNeverInjected) {
    // Not UTF-8, a quote, a backslash, a newline: the JSON still parses and
    // holds the name (the bad byte as U+FFFD).
    const SceneDesc scene = test::sceneFromText("/sphere s 10 0 0 0\n");
    GltfOptions options;
    options.source = "we\xffird\"q\\u0022\n.f2";
    const json gltf = json::parse(gltfScene(scene, options).json);
    EXPECT_EQ(gltf["scenes"][0]["name"], "we\xef\xbf\xbdird\"q\\u0022\n.f2");
}

TEST(GltfExport, BufferFileNamesArePercentEncoded) {
    EXPECT_EQ(uriOfFileName("demo.bin"), "demo.bin");
    EXPECT_EQ(uriOfFileName("a b#1%?.bin"), "a%20b%231%25%3F.bin");
    EXPECT_EQ(uriOfFileName("\xc3\xa9.bin"), "%C3%A9.bin");
}

}  // namespace
}  // namespace f2
