#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <tuple>

#include "math/Bounds.h"
#include "scene/AssetFiles.h"
#include "scene/GltfImporter.h"
#include "scene/MeshNormals.h"
#include "scene/Deformation.h"
#include "scene/ObjImporter.h"
#include "scene/ScenePose.h"
#include "scene/StrictJson.h"

using namespace specula;
using namespace specula::scene;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path kAssets = fs::path(SPECULA_TEST_DATA_DIR) / "scenes" / "good" / "assets";

std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string u32(std::uint32_t value) {
  std::string bytes(4, '\0');
  std::memcpy(bytes.data(), &value, 4);
  return bytes;
}

std::string floats(std::initializer_list<float> values) {
  std::string bytes(values.size() * sizeof(float), '\0');
  std::memcpy(bytes.data(), values.begin(), bytes.size());
  return bytes;
}

std::string padded(std::string bytes, char fill) {
  while (bytes.size() % 4 != 0) bytes += fill;
  return bytes;
}

// A GLB container around `document` and an optional BIN chunk, framed as the spec says.
std::string glb(const json& document, const std::string& bin) {
  const std::string text = padded(document.dump(), ' '), payload = padded(bin, '\0');
  const std::size_t length = 12 + 8 + text.size() + (payload.empty() ? 0 : 8 + payload.size());
  std::string bytes = "glTF" + u32(2) + u32(static_cast<std::uint32_t>(length)) +
                      u32(static_cast<std::uint32_t>(text.size())) + "JSON" + text;
  if (!payload.empty()) bytes += u32(static_cast<std::uint32_t>(payload.size())) + std::string("BIN\0", 4) + payload;
  return bytes;
}

const std::string kTriangle = floats({0, 0, 0, 1, 0, 0, 0, 1, 0});

// One triangle, positions only, stored in the GLB's BIN chunk (or in "tri.bin" once a uri is added).
json triangleGltf() {
  return json::parse(R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 36}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
    "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0}}]}]})");
}

void expectValidMesh(const Mesh& mesh) {
  ASSERT_EQ(mesh.indices.size() % 3, 0u);
  for (std::uint32_t index : mesh.indices) ASSERT_LT(index, mesh.vertices.size());
  for (const Vertex& v : mesh.vertices) {
    ASSERT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z));
    ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
  }
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected) {
  EXPECT_NEAR(actual.x, expected.x, 1e-5f);
  EXPECT_NEAR(actual.y, expected.y, 1e-5f);
  EXPECT_NEAR(actual.z, expected.z, 1e-5f);
}

// Each test gets a scratch folder for the assets it writes.
class Importer : public testing::Test {
 protected:
  void SetUp() override {
    const testing::TestInfo* info = testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(testing::TempDir()) / ("specula-" + std::string(info->test_suite_name()) + "-" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, std::string_view bytes) {
    const fs::path file = dir_ / name;
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return file;
  }

  Result<Mesh> gltf(const std::string& bytes, const GltfMeshSelector& which = {}) {
    return importGltf(write("asset.glb", bytes), which, "imported");
  }

  Result<Mesh> obj(std::string_view text) { return importObj(write("asset.obj", text), "imported"); }

  // The glTF with `edit` applied to triangleGltf() must fail with a message containing `expected`.
  void expectGltfFailure(const std::function<void(json&)>& edit, const std::string& expected,
                         const std::string& bin = kTriangle) {
    json document = triangleGltf();
    edit(document);
    Result<Mesh> mesh = gltf(glb(document, bin));
    ASSERT_FALSE(mesh.ok()) << "expected failure: " << expected;
    EXPECT_NE(mesh.error().find(expected), std::string::npos) << "message: " << mesh.error() << "\nlacks: " << expected;
    EXPECT_TRUE(mesh.error().starts_with((dir_ / "asset.glb").string() + ": ")) << mesh.error();
  }

  // `document`, edited by `edit`, in a GLB with `bin` must fail to import as a scene with a message
  // containing `expected`.
  void expectSceneRefused(json document, const std::string& bin, const std::function<void(json&)>& edit,
                          const std::string& expected) {
    edit(document);
    Result<ImportedGltfScene> imported = importGltfScene(write("asset.glb", glb(document, bin)));
    ASSERT_FALSE(imported.ok()) << expected;
    EXPECT_NE(imported.error().find(expected), std::string::npos)
        << "message: " << imported.error() << "\nlacks: " << expected;
  }

  void expectObjFailure(std::string_view text, const std::string& expected) {
    Result<Mesh> mesh = obj(text);
    ASSERT_FALSE(mesh.ok()) << "expected failure: " << expected;
    EXPECT_NE(mesh.error().find(expected), std::string::npos) << "message: " << mesh.error() << "\nlacks: " << expected;
    EXPECT_TRUE(mesh.error().starts_with((dir_ / "asset.obj").string() + ": ")) << mesh.error();
  }

  fs::path dir_;
};

}  // namespace

// ---- OBJ -------------------------------------------------------------------------------------------

TEST_F(Importer, ObjPyramidFanSplitsItsQuadAndGetsSmoothNormalsAcrossUvSeams) {
  Result<Mesh> mesh = importObj(kAssets / "pyramid.obj", "pyramid");
  ASSERT_TRUE(mesh.ok()) << mesh.error();
  EXPECT_EQ(mesh->name, "pyramid");
  EXPECT_EQ(mesh->triangleCount(), 6u);
  expectValidMesh(mesh.value());
  for (const Vertex& a : mesh->vertices) {
    if (a.position == glm::vec3(0, 1, 0)) expectNear(a.normal, {0, 1, 0});
    for (const Vertex& b : mesh->vertices)
      if (a.position == b.position) expectNear(a.normal, b.normal);  // base corners appear with and without uv
  }
}

TEST_F(Importer, ObjSharesCornersAndNormalizesTheFilesNormals) {
  Result<Mesh> mesh =
      obj("v 0 0 0\nv 1 0 0\nv 1 0 -1\nv 0 0 -1\nvt 0 0\nvt 1 1\nvn 0 3 0\n"
          "f 1/1/1 2/1/1 3/2/1\nf 1/1/1 3/2/1 4/1/1\n");
  ASSERT_TRUE(mesh.ok()) << mesh.error();
  EXPECT_EQ(mesh->vertices.size(), 4u);
  EXPECT_EQ(mesh->indices.size(), 6u);
  for (const Vertex& v : mesh->vertices) expectNear(v.normal, {0, 1, 0});
  EXPECT_EQ(mesh->vertices[2].uv, glm::vec2(1, 1));
}

TEST_F(Importer, ObjWithoutUvGetsZeroUvAndAcceptsRelativeIndicesAndAnyLineEnding) {
  Result<Mesh> mesh = obj("v 0 0 0\r\nv 1 0 0\rv 0 1 0\nf -3 -2 -1\n");
  ASSERT_TRUE(mesh.ok()) << mesh.error();
  ASSERT_EQ(mesh->vertices.size(), 3u);
  EXPECT_EQ(mesh->vertices[1].uv, glm::vec2(0));
  expectNear(mesh->vertices[0].normal, {0, 0, 1});
}

TEST_F(Importer, ObjTagLinesCannotAmplifyMemory) {
  // tinyobjloader would reserve 8192 values for each of these lines: tens of gigabytes in all.
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  for (int i = 0; i < 200000; ++i) text += "  t crease 8192/8192/8192\n";
  Result<Mesh> mesh = obj(text);
  ASSERT_TRUE(mesh.ok()) << mesh.error();
  EXPECT_EQ(mesh->triangleCount(), 1u);
}

TEST_F(Importer, ObjRefusesBrokenInputWithTheProblem) {
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expectObjFailure(triangle + "f 1 2 4\n", "face 1 refers to vertex 4, but the file defines 3");
  expectObjFailure(triangle + "f 1 2 3\nf -9 1 2\n", "face 2 refers to vertex -5, but the file defines 3");
  expectObjFailure(triangle + "vt 0 0\nf 1/1 2/2 3/1\n",
                   "face 1 refers to texture coordinate 2, but the file defines 1");
  expectObjFailure(triangle + "vn 0 0 1\nf 1//1 2//1 3//2\n", "face 1 refers to normal 2, but the file defines 1");
  expectObjFailure(triangle + "f 0 1 2\n", "not a valid OBJ file");
  expectObjFailure("v 0 0 1e999\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "vertex 1 has a non-finite coordinate");
  expectObjFailure(triangle + "vn 0 0 0\nf 1//1 2//1 3//1\n", "normal 1 is zero or not finite");
  expectObjFailure(triangle + "vt 0 1e999\nf 1/1 2/1 3/1\n", "texture coordinate 1 is not finite");
  expectObjFailure(triangle, "has no faces");
  expectObjFailure("", "empty file");
  std::string bigFace = "f";
  for (int i = 0; i < 256; ++i) bigFace += " 1";
  expectObjFailure(triangle + bigFace + "\n", "face 1 has more than 255 corners");
}

TEST_F(Importer, ObjRefusesGarbageMissingFilesAndDirectories) {
  std::mt19937 random(11);
  std::string garbage(8192, '\0');
  for (char& c : garbage) c = static_cast<char>(random() % 256);
  Result<Mesh> mesh = obj(garbage);
  if (mesh.ok()) expectValidMesh(mesh.value());  // stray "v"/"f" lines may survive; they must still be sound
  EXPECT_FALSE(importObj(dir_ / "missing.obj", "m").ok());
  fs::create_directories(dir_ / "folder.obj");
  Result<Mesh> folder = importObj(dir_ / "folder.obj", "m");
  ASSERT_FALSE(folder.ok());
  EXPECT_NE(folder.error().find("is a directory"), std::string::npos) << folder.error();
}

TEST_F(Importer, ObjMutationsNeverCrashAndYieldOnlySoundMeshes) {
  const std::string original = readAll(kAssets / "pyramid.obj");
  std::mt19937 random(5);
  for (int round = 0; round < 300; ++round) {
    std::string bytes = original;
    for (int flips = 0; flips < 4; ++flips) bytes[random() % bytes.size()] = "0123456789 -/\nfvt.e"[random() % 19];
    Result<Mesh> mesh = obj(bytes);
    if (mesh.ok()) expectValidMesh(mesh.value());
  }
}

// ---- glTF ------------------------------------------------------------------------------------------

TEST_F(Importer, GltfQuadPickedByNameKeepsItsNormalsAndUv) {
  Result<Mesh> mesh = importGltf(kAssets / "quad.gltf", std::string("quad"), "quad");
  ASSERT_TRUE(mesh.ok()) << mesh.error();
  EXPECT_EQ(mesh->vertices.size(), 4u);
  EXPECT_EQ(mesh->indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
  for (const Vertex& v : mesh->vertices) expectNear(v.normal, {0, 1, 0});
  EXPECT_EQ(mesh->vertices[2].uv, glm::vec2(1, 1));
  expectNear(mesh->vertices[2].position, {1, 0, 1});
}

TEST_F(Importer, GltfMeshByIndexFromAnExternalBufferIsFlatShadedWithoutNormals) {
  Result<Mesh> mesh = importGltf(kAssets / "quad-external.gltf", std::size_t{1}, "triangle");
  ASSERT_TRUE(mesh.ok()) << mesh.error();
  ASSERT_EQ(mesh->vertices.size(), 3u);
  for (const Vertex& v : mesh->vertices) expectNear(v.normal, {0, 0, 1});
}

TEST_F(Importer, GlbWithNormalizedIntegerUvAndByteIndicesImports) {
  Result<Mesh> mesh = importGltf(kAssets / "wedge.glb", {}, "wedge");
  ASSERT_TRUE(mesh.ok()) << mesh.error();
  EXPECT_EQ(mesh->triangleCount(), 2u);
  EXPECT_EQ(mesh->vertices.size(), 6u);
  expectValidMesh(mesh.value());
  EXPECT_EQ(mesh->vertices[1].uv, glm::vec2(1, 0));
}

TEST_F(Importer, GltfRefusesToGuessAmongSeveralMeshesAndListsThem) {
  Result<Mesh> unchosen = importGltf(kAssets / "quad.gltf", {}, "m");
  ASSERT_FALSE(unchosen.ok());
  EXPECT_NE(unchosen.error().find("holds 2 meshes (0 \"quad\", 1 \"triangle\"); pick one"), std::string::npos)
      << unchosen.error();
  Result<Mesh> unknown = importGltf(kAssets / "quad.gltf", std::string("cube"), "m");
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.error().find("no mesh named \"cube\""), std::string::npos) << unknown.error();
}

// ---- glTF scenes -------------------------------------------------------------------------------------

const fs::path kGltfScenes = fs::path(SPECULA_TEST_DATA_DIR) / "gltf";

const SceneObject* objectNamed(const Scene& scene, const std::string& name) {
  for (const SceneObject& object : scene.objects)
    if (object.name == name) return &object;
  return nullptr;
}

// The node tree's cube: root (translate (1, 0, 0), quaternion 90° about y) > child (translate
// (0, 1, 0), scale 2) > cube (matrix: translate (0, 0, 3)), a unit cube about its origin. By hand:
// the cube's z in [2.5, 3.5] becomes [5, 7] scaled and y [-1, 1] + 1 = [0, 2]; the quarter turn
// about y sends (x, y, z) to (z, y, -x), and the root adds 1 to x: x in [6, 8], y in [0, 2], z in [-1, 1].
TEST_F(Importer, GltfSceneComposesNodeTransformsDownTheTree) {
  for (const char* file : {"node-tree.gltf", "node-tree-external.gltf"}) {
    Result<ImportedGltfScene> imported = importGltfScene(kGltfScenes / file);
    ASSERT_TRUE(imported.ok()) << imported.error();
    const Scene& scene = imported->scene;
    ASSERT_EQ(scene.objects.size(), 2u) << file;
    const SceneObject* cube = objectNamed(scene, "cube");
    ASSERT_NE(cube, nullptr);
    math::Bounds bounds;
    for (const Vertex& v : scene.meshes[cube->mesh].vertices) {
      bounds.add(v.position);
      EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
    }
    expectNear(bounds.low, {6, 0, -1});
    expectNear(bounds.high, {8, 2, 1});
    // A chrome material (metallic 1, roughness 0.05) on a closed mesh is a mirror; the red quad is not.
    ASSERT_TRUE(cube->mirror.has_value());
    EXPECT_TRUE(cube->mirror->closed);
    EXPECT_NEAR(scene.materials[cube->material].reflectivity, 0.9f, 1e-6f);
    const SceneObject* ground = objectNamed(scene, "ground");
    ASSERT_NE(ground, nullptr);
    EXPECT_FALSE(ground->mirror.has_value());
    expectNear(scene.materials[ground->material].baseColor, {0.8f, 0.1f, 0.1f});
    // The camera node at (7, 3, 12) looks down its -z; yfov 0.7 rad.
    expectNear(scene.camera.eye, {7, 3, 12});
    expectNear(glm::normalize(scene.camera.target - scene.camera.eye), {0, 0, -1});
    EXPECT_NEAR(scene.camera.fovYDegrees, glm::degrees(0.7f), 1e-4f);
    // The sun, turned 45° about x, shines down -z: towards it is (0, sin 45°, cos 45°).
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].kind, Light::Kind::Directional);
    expectNear(scene.lights[0].vector, {0, std::sqrt(0.5f), std::sqrt(0.5f)});
    EXPECT_FLOAT_EQ(scene.lights[0].intensity, 1.0f);
    EXPECT_TRUE(imported->scene.notes.empty());
  }
}

TEST_F(Importer, GltfSceneWithoutCameraOrLightsFramesItAndLightsItByDefault) {
  json document = triangleGltf();
  document["nodes"] = json::parse(R"([{"mesh": 0, "translation": [10, 0, 0]}])");
  document["scenes"] = json::parse(R"([{"nodes": [0]}])");
  Result<ImportedGltfScene> imported = importGltfScene(write("asset.glb", glb(document, kTriangle)));
  ASSERT_TRUE(imported.ok()) << imported.error();
  const Scene& scene = imported->scene;
  ASSERT_EQ(scene.lights.size(), 1u);
  // The triangle's bounds (10..11, 0..1, 0) centred in view.
  expectNear(scene.camera.target, {10.5f, 0.5f, 0.0f});
  EXPECT_FALSE(math::cameraProblem(scene.camera).has_value());
}

TEST_F(Importer, GltfSceneRefusesBrokenTreesAndChoicesByName) {
  const GltfSceneChoice byDefault;
  GltfSceneChoice sceneTwo, cameraZero;
  sceneTwo.scene = 2;
  cameraZero.camera = 0;
  const auto expectSceneFailure = [&](const char* nodes, const char* scenes, const std::string& expected,
                                      const GltfSceneChoice* choice = nullptr) {
    json document = triangleGltf();
    document["nodes"] = json::parse(nodes);
    document["scenes"] = json::parse(scenes);
    Result<ImportedGltfScene> imported =
        importGltfScene(write("asset.glb", glb(document, kTriangle)), choice ? *choice : byDefault);
    ASSERT_FALSE(imported.ok()) << expected;
    EXPECT_NE(imported.error().find(expected), std::string::npos)
        << "message: " << imported.error() << "\nlacks: " << expected;
  };
  expectSceneFailure(R"([{"mesh": 0, "children": [1]}, {"children": [0]}])", R"([{"nodes": [0]}])",
                     "node 0 is reached twice: the node tree has a cycle or a node with two parents");
  expectSceneFailure(R"([{"children": [2]}, {"children": [2]}, {"mesh": 0}])", R"([{"nodes": [0, 1]}])",
                     "node 2 is reached twice");
  expectSceneFailure(R"([{"mesh": 0}])", R"([{"nodes": [3]}])", "scene 0 refers to node 3, but the file has 1");
  expectSceneFailure(R"([{"mesh": 0}])", R"([])", "the file holds no scene");
  expectSceneFailure(
      R"([{"mesh": 0}])", R"([{"nodes": [0]}])",
      "there is no scene 2 (the file has 1; pick one of 0..0 with --gltf-scene, or \"scene\" in an include)",
      &sceneTwo);
  expectSceneFailure(R"([{"mesh": 0}])", R"([{"nodes": [0]}])", "there is no camera 0 (the file has 0)", &cameraZero);
  expectSceneFailure(R"([{"mesh": 0, "translation": [1, 2]}])", R"([{"nodes": [0]}])",
                     "node 0: translation must have 3 numbers");
  expectSceneFailure(R"([{"mesh": 0, "rotation": [0, 0, 0, 0]}])", R"([{"nodes": [0]}])",
                     "node 0: rotation is a zero quaternion");
  expectSceneFailure(R"([{"mesh": 5}])", R"([{"nodes": [0]}])", "node 0 refers to mesh 5, but the file has 1");
  expectSceneFailure(R"([{"camera": 0}])", R"([{"nodes": [0]}])", "scene 0 draws no mesh");
}

TEST_F(Importer, GltfSceneMakesAnOpenChromeMeshATwoSidedMirrorAndSaysSo) {
  json document = triangleGltf();  // one triangle: open
  document["materials"] = json::parse(R"([{"pbrMetallicRoughness": {"metallicFactor": 1.0, "roughnessFactor": 0.0}}])");
  document["meshes"][0]["primitives"][0]["material"] = 0;
  document["nodes"] = json::parse(R"([{"mesh": 0, "name": "shard"}])");
  document["scenes"] = json::parse(R"([{"nodes": [0]}])");
  Result<ImportedGltfScene> imported = importGltfScene(write("asset.glb", glb(document, kTriangle)));
  ASSERT_TRUE(imported.ok()) << imported.error();
  const SceneObject& shard = imported->scene.objects[0];
  ASSERT_TRUE(shard.mirror.has_value());
  EXPECT_TRUE(shard.mirror->twoSided());
  EXPECT_GT(imported->scene.materials[shard.material].reflectivity, 0.9f);
  ASSERT_EQ(imported->scene.notes.size(), 1u);
  EXPECT_EQ(imported->scene.notes[0],
            "'shard' is an open mesh: a two-sided mirror whose reflections are ray-cast (only a closed mesh can be "
            "searched)");
}

TEST_F(Importer, GltfSceneNamesTheAttributesAndExtensionsItDoesNotRead) {
  json document = triangleGltf();
  document["nodes"] = json::parse(R"([{"mesh": 0, "name": "leaf"}])");
  document["scenes"] = json::parse(R"([{"nodes": [0]}])");
  document["extensionsUsed"] = json::parse(R"(["KHR_lights_punctual", "KHR_materials_clearcoat"])");
  // A second UV set and tangent displacements (the POSITION accessor stands in for both: never read).
  document["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] = 0;
  document["meshes"][0]["primitives"][0]["targets"] = json::parse(R"([{"POSITION": 0, "TANGENT": 0}])");
  Result<ImportedGltfScene> imported = importGltfScene(write("asset.glb", glb(document, kTriangle)));
  ASSERT_TRUE(imported.ok()) << imported.error();
  ASSERT_EQ(imported->scene.notes.size(), 3u);
  EXPECT_EQ(imported->scene.notes[0], "vertex attribute TEXCOORD_1 (on 1 primitive) is not read");
  EXPECT_EQ(imported->scene.notes[1], "morph target TANGENT displacements (on 1 primitive) are not read");
  EXPECT_EQ(imported->scene.notes[2], "extension KHR_materials_clearcoat is not read: what it adds is left out");
}

// ---- glTF animations ---------------------------------------------------------------------------------

// Where the object's own origin is drawn at `seconds`.
glm::vec3 originAt(const Scene& scene, const std::string& name, double seconds) {
  const ScenePose pose = ScenePose::at(scene, seconds);
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].name == name) return glm::vec3(pose.objectToWorld[i] * glm::vec4(0, 0, 0, 1));
  ADD_FAILURE() << "no object " << name;
  return glm::vec3(0.0f);
}

float drawnScaleAt(const Scene& scene, const std::string& name, double seconds) {
  const ScenePose pose = ScenePose::at(scene, seconds);
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].name == name) return glm::length(glm::vec3(pose.objectToWorld[i][0]));
  ADD_FAILURE() << "no object " << name;
  return 0.0f;
}

// animated.glb (tests/data/gltf/make_gltf_scenes.py): the places below are worked from the keys written there.
TEST_F(Importer, GltfAnimationsMoveTheNodesTheirChannelsTargetAndTheObjectsBelowThem) {
  Result<ImportedGltfScene> imported = importGltfScene(kGltfScenes / "animated.glb");
  ASSERT_TRUE(imported.ok()) << imported.error();
  const Scene& scene = imported->scene;
  EXPECT_TRUE(scene.moves());
  EXPECT_TRUE(scene.notes.empty()) << scene.notes.front();
  ASSERT_EQ(scene.rig.clips.size(), 2u);
  EXPECT_EQ(scene.rig.clips[0].name, "show");
  EXPECT_DOUBLE_EQ(scene.rig.clips[0].duration, 2.0);
  EXPECT_DOUBLE_EQ(scene.rig.clips[1].duration, 4.0);
  ASSERT_NE(objectNamed(scene, "mirror"), nullptr);
  EXPECT_TRUE(objectNamed(scene, "mirror")->mirror.has_value()) << "a closed chrome mesh stays a mirror when it moves";
  // LINEAR translation: y 1.2 → 1.7 over the first second; the clip loops after 2 s.
  expectNear(originAt(scene, "mirror", 0.5), {0, 1.45f, 0});
  expectNear(originAt(scene, "mirror", 2.5), {0, 1.45f, 0});
  // The carousel turns 360° in 2 s (keys every 120°), carrying the red box from (2.5, 0.4, 0): 45° at 0.25 s.
  const float c = 2.5f * std::cos(glm::radians(45.0f));
  expectNear(originAt(scene, "red box", 0.25), {c, 0.4f, -c});
  expectNear(originAt(scene, "red box", 1.0), {-2.5f, 0.4f, 0});
  // STEP scale: 1 until 1 s, then 0.5.
  EXPECT_NEAR(drawnScaleAt(scene, "green box", 0.999), 1.0f, 1e-6f);
  EXPECT_NEAR(drawnScaleAt(scene, "green box", 1.0), 0.5f, 1e-6f);
  // CUBICSPLINE over 2 s: x on the straight line from -1.5 to 1.5; y tangents of 1 a second lift it by
  // 2(w³ - 2w² + w) + 2(w³ - w²) = 2(2w³ - 3w² + w), at w = ¼: 0.1875.
  expectNear(originAt(scene, "blue box", 0.5), {-0.75f, 0.5875f, 2.6f});
  expectNear(originAt(scene, "blue box", 1.0), {0, 0.4f, 2.6f});
  // The floor is still: stored in world space, drawn at the identity.
  EXPECT_EQ(ScenePose::at(scene, 1.0).objectToWorld[0], glm::mat4(1.0f));
  // "dolly" moves the camera from z 9 to 7 over 4 s.
  expectNear(ScenePose::at(scene, 2.0).camera.eye, {0, 3, 8});
  expectNear(scene.camera.eye, {0, 3, 9});
}

TEST_F(Importer, GltfAnimationChoicePlaysAllNoneOrOneAndNamesTheRest) {
  GltfSceneChoice choice;
  choice.animation = "none";
  Result<ImportedGltfScene> still = importGltfScene(kGltfScenes / "animated.glb", choice);
  ASSERT_TRUE(still.ok()) << still.error();
  EXPECT_FALSE(still->scene.moves());
  EXPECT_TRUE(still->scene.rig.nodes.empty()) << "a still scene needs no rig";
  ASSERT_EQ(still->scene.notes.size(), 1u);
  EXPECT_EQ(still->scene.notes[0], "2 animations not played (--animation none; all plays every one)");
  math::Bounds ball;
  for (const Vertex& v : still->scene.meshes[objectNamed(still->scene, "mirror")->mesh].vertices) ball.add(v.position);
  expectNear(ball.center(), {0, 1.2f, 0});  // in world space, at its rest place

  for (const char* dolly : {"dolly", "1"}) {
    choice.animation = dolly;
    Result<ImportedGltfScene> one = importGltfScene(kGltfScenes / "animated.glb", choice);
    ASSERT_TRUE(one.ok()) << one.error();
    ASSERT_EQ(one->scene.rig.clips.size(), 1u) << dolly;
    EXPECT_EQ(one->scene.rig.clips[0].name, "dolly");
    EXPECT_TRUE(one->scene.rig.objects.empty()) << "only the camera moves";
    expectNear(ScenePose::at(one->scene, 4.0 - 1e-9).camera.eye, {0, 3, 7});
    expectNear(originAt(one->scene, "mirror", 1.0), {0, 0, 0});  // baked where it rests
  }
  choice.animation = "walk";
  Result<ImportedGltfScene> missing = importGltfScene(kGltfScenes / "animated.glb", choice);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().find("there is no animation \"walk\" (the file has 0 \"show\", 1 \"dolly\"); name one, "
                                 "or all or none, with --animation"),
            std::string::npos)
      << missing.error();
}

// One triangle on node 0 with key data in the buffer after it: accessor 1 times (0, 1), 2 two translations,
// 3 two quaternions, 4 times (1, 0.5), 5 quaternions the first of which is zero.
json animatedTriangle(json animation) {
  json document = triangleGltf();
  document["nodes"] = json::parse(R"([{"mesh": 0}, {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}])");
  document["scenes"] = json::parse(R"([{"nodes": [0, 1]}])");
  document["buffers"][0]["byteLength"] = 36 + 8 + 24 + 32 + 8 + 32;
  document["bufferViews"] =
      json::parse(R"([{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 8},
    {"buffer": 0, "byteOffset": 44, "byteLength": 24}, {"buffer": 0, "byteOffset": 68, "byteLength": 32},
    {"buffer": 0, "byteOffset": 100, "byteLength": 8}, {"buffer": 0, "byteOffset": 108, "byteLength": 32}])");
  for (const auto& [view, type, count] :
       {std::tuple{1, "SCALAR", 2}, {2, "VEC3", 2}, {3, "VEC4", 2}, {4, "SCALAR", 2}, {5, "VEC4", 2}})
    document["accessors"].push_back({{"bufferView", view}, {"componentType", 5126}, {"count", count}, {"type", type}});
  document["animations"] = json::array({std::move(animation)});
  return document;
}

const std::string kAnimationData = kTriangle + floats({0, 1}) + floats({0, 0, 0, 1, 0, 0}) +
                                   floats({0, 0, 0, 1, 0, 1, 0, 0}) + floats({1, 0.5f}) +
                                   floats({0, 0, 0, 0, 0, 0, 0, 1});

TEST_F(Importer, GltfAnimationsThatAreMalformedAreRefusedByTheirJsonPath) {
  const json good = json::parse(R"({"channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}],
                                    "samplers": [{"input": 1, "output": 2}]})");
  Result<ImportedGltfScene> played = importGltfScene(write("asset.glb", glb(animatedTriangle(good), kAnimationData)));
  ASSERT_TRUE(played.ok()) << played.error();
  expectNear(originAt(played->scene, "node 0", 0.25), {0.25f, 0, 0});

  const auto expectRefused = [&](const std::function<void(json&)>& edit, const std::string& expected) {
    expectSceneRefused(
        animatedTriangle(good), kAnimationData, [&](json& d) { edit(d["animations"][0]); }, expected);
  };
  expectRefused([](json& a) { a["channels"][0]["sampler"] = 5; },
                "$.animations[0].channels[0].sampler: refers to sampler 5, but the animation has 1");
  expectRefused([](json& a) { a["channels"][0]["target"]["path"] = "colour"; },
                "$.animations[0].channels[0].target.path: \"colour\" is not translation, rotation, scale or weights");
  expectRefused([](json& a) { a["channels"][0]["target"]["node"] = 7; },
                "$.animations[0].channels[0].target.node: refers to node 7, but the file has 2");
  expectRefused([](json& a) { a["channels"][0]["target"]["node"] = 1; },
                "$.animations[0].channels[0].target.node: node 1 has a matrix");
  expectRefused([](json& a) { a["samplers"][0]["interpolation"] = "BOUNCY"; },
                "$.animations[0].samplers[0].interpolation: \"BOUNCY\" is not LINEAR, STEP or CUBICSPLINE");
  expectRefused([](json& a) { a["samplers"][0]["input"] = 2; },
                "accessor 2 ($.animations[0].samplers[0].input): has VEC3 elements, expected SCALAR");
  expectRefused([](json& a) { a["samplers"][0]["input"] = 4; },
                "accessor 4 ($.animations[0].samplers[0].input): key 1 is at 0.5");
  expectRefused([](json& a) { a["samplers"][0]["interpolation"] = "CUBICSPLINE"; },
                "accessor 2 ($.animations[0].samplers[0].output): 2 values for 2 keys; CUBICSPLINE needs 3 a key");
  expectRefused([](json& a) { a["channels"][0]["target"]["path"] = "rotation"; },
                "accessor 2 ($.animations[0].samplers[0].output): has VEC3 elements, expected VEC4");
  expectRefused(
      [](json& a) {
        a["channels"][0]["target"]["path"] = "rotation";
        a["samplers"][0]["output"] = 5;
      },
      "accessor 5 ($.animations[0].samplers[0].output): value 0 is a zero quaternion");
  expectRefused([](json& a) { a["samplers"][0]["output"] = 9; },
                "$.animations[0].samplers[0].output refers to accessor 9, but the file has 6");
}

// ---- glTF morph targets --------------------------------------------------------------------------------

const Mesh& meshOf(const Scene& scene, const std::string& name) { return scene.meshes[objectNamed(scene, name)->mesh]; }

std::vector<float> weightsAt(const Scene& scene, const std::string& name, double seconds) {
  const ScenePose pose = ScenePose::at(scene, seconds);
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].name == name) return pose.morphWeights[i];
  ADD_FAILURE() << "no object " << name;
  return {};
}

// morphing.glb (tests/data/gltf/make_gltf_scenes.py): the weights below are worked from the keys written there.
TEST_F(Importer, GltfMorphTargetsTakeTheWeightsTheirKeysGiveAtEveryTime) {
  Result<ImportedGltfScene> imported = importGltfScene(kGltfScenes / "morphing.glb");
  ASSERT_TRUE(imported.ok()) << imported.error();
  const Scene& scene = imported->scene;
  EXPECT_TRUE(scene.notes.empty()) << scene.notes.front();
  EXPECT_TRUE(scene.moves());
  ASSERT_EQ(scene.rig.morphed.size(), 2u);
  EXPECT_EQ(meshOf(scene, "cloth").morphTargets.size(), 2u);
  EXPECT_EQ(meshOf(scene, "red box").morphTargets.size(), 1u);
  EXPECT_TRUE(meshOf(scene, "mirror").morphTargets.empty());
  EXPECT_TRUE(weightsAt(scene, "mirror", 0.5).empty()) << "what does not morph has no weights";
  // The cloth's LINEAR keys: (0, 0) at 0 s, (1, 0.5) at 1 s, (0, 1) at 2 s; the clip loops.
  for (const auto& [seconds, wave, bulge] :
       {std::tuple{0.5, 0.5f, 0.25f}, {1.0, 1.0f, 0.5f}, {1.5, 0.5f, 0.75f}, {2.5, 0.5f, 0.25f}}) {
    const std::vector<float> weights = weightsAt(scene, "cloth", seconds);
    ASSERT_EQ(weights.size(), 2u);
    EXPECT_NEAR(weights[0], wave, 1e-6f) << seconds;
    EXPECT_NEAR(weights[1], bulge, 1e-6f) << seconds;
  }
  // The red box's CUBICSPLINE key pair with zero tangents over 2 s: 3w² - 2w³, at w = ¼: 0.15625.
  EXPECT_NEAR(weightsAt(scene, "red box", 0.5)[0], 0.15625f, 1e-6f);
  EXPECT_NEAR(weightsAt(scene, "red box", 1.0)[0], 0.5f, 1e-6f);
  // A vertex of the cloth at weights (1, 0.5): x from the grid's left edge, z the wave plus half the bulge.
  const Mesh& cloth = meshOf(scene, "cloth");
  const std::vector<Vertex> morphed = deformedVertices(cloth, weightsAt(scene, "cloth", 1.0), {});
  const std::size_t v = 8 * 25 + 3;  // row 8 (mid height), column 3 of the 24 x 16 grid
  const float x = 4.0f * (3.0f / 24.0f - 0.5f);
  expectNear(morphed[v].position, {x, 0.0f, 0.35f * std::sin(2.0f * glm::pi<float>() / 4.0f * x) + 0.5f * 0.6f});
  EXPECT_NEAR(glm::length(morphed[v].normal), 1.0f, 1e-6f);
  EXPECT_LT(morphed[v].normal.z, 0.99f) << "the wave tilts the normal";
  // Its bounds hold every morphed vertex, at every weight the keys reach.
  const DeformationExtents extents = deformationExtents(cloth, 0);
  for (double t = 0.0; t < 2.0; t += 0.125) {
    const std::vector<float> weights = weightsAt(scene, "cloth", t);
    const math::Bounds bounds = deformedBounds(extents, weights, {});
    for (const Vertex& vertex : deformedVertices(cloth, weights, {})) {
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(vertex.position, bounds.low - 1e-6f))) << t;
      EXPECT_TRUE(glm::all(glm::lessThanEqual(vertex.position, bounds.high + 1e-6f))) << t;
    }
  }

  // Unplayed, the cloth keeps its node's weights (0.2, 0), applied when loading.
  GltfSceneChoice still;
  still.animation = "none";
  Result<ImportedGltfScene> baked = importGltfScene(kGltfScenes / "morphing.glb", still);
  ASSERT_TRUE(baked.ok()) << baked.error();
  EXPECT_TRUE(baked->scene.rig.morphed.empty());
  EXPECT_TRUE(meshOf(baked->scene, "cloth").morphTargets.empty());
  const glm::vec3 world = meshOf(baked->scene, "cloth").vertices[v].position;  // a still scene is in world space
  // The node turns the cloth 90° about y: its x runs along −z, its displacements along +x.
  expectNear(world, {-2.2f + 0.2f * 0.35f * std::sin(2.0f * glm::pi<float>() / 4.0f * x), 1.4f, 0.6f - x});
}

TEST_F(Importer, GltfMorphTargetsThatAreMalformedAreRefusedByTheirJsonPath) {
  const json weights = json::parse(R"({"channels": [{"sampler": 0, "target": {"node": 0, "path": "weights"}}],
                                       "samplers": [{"input": 1, "output": 1}]})");
  const auto morphingTriangle = [](json animation, const json& targets) {
    json document = animatedTriangle(std::move(animation));
    document["meshes"][0]["primitives"][0]["targets"] = targets;
    return document;
  };
  const json oneTarget = json::parse(R"([{"POSITION": 0}])");
  Result<ImportedGltfScene> played =
      importGltfScene(write("asset.glb", glb(morphingTriangle(weights, oneTarget), kAnimationData)));
  ASSERT_TRUE(played.ok()) << played.error();
  ASSERT_EQ(played->scene.rig.morphed.size(), 1u);
  EXPECT_NEAR(weightsAt(played->scene, "node 0", 0.25)[0], 0.25f, 1e-6f) << "the key times (0, 1) are the weights";

  const auto expectRefused = [&](const std::function<void(json&)>& edit, const std::string& expected) {
    expectSceneRefused(morphingTriangle(weights, oneTarget), kAnimationData, edit, expected);
  };
  expectRefused([](json& d) { d["animations"][0]["channels"][0]["target"]["node"] = 1; },
                "$.animations[0].channels[0].target.node: node 1 has no mesh with morph targets for its weights");
  expectRefused([](json& d) { d["animations"][0]["samplers"][0]["output"] = 2; },
                "accessor 2 ($.animations[0].samplers[0].output): has VEC3 elements, expected SCALAR");
  expectRefused([](json& d) { d["meshes"][0]["primitives"][0]["targets"] = json::parse(R"([{"POSITION": 0}, {}])"); },
                "accessor 1 ($.animations[0].samplers[0].output): 2 values for 2 keys of 2 morph target weights");
  expectRefused([](json& d) { d["meshes"][0]["primitives"][0]["targets"][0]["POSITION"] = 3; },
                "(morph target 0 POSITION of primitive 0 of mesh 0): has VEC4 elements, expected VEC3");
  expectRefused([](json& d) { d["meshes"][0]["primitives"][0]["targets"][0]["NORMAL"] = 1; },
                "(morph target 0 NORMAL of primitive 0 of mesh 0): has SCALAR elements, expected VEC3");
  expectRefused(
      [](json& d) {
        d["nodes"][0]["weights"] = json::array({0.5, 0.5});
      },
      "node 0 or its mesh 0 has 2 weights for 1 morph targets");
  expectRefused(
      [](json& d) {
        d["meshes"][0]["primitives"].push_back(d["meshes"][0]["primitives"][0]);
        d["meshes"][0]["primitives"][1].erase("targets");
      },
      "$.meshes[0].primitives[1].targets: 0 morph targets, but primitive 0 has 1");
}

// ---- glTF skins ---------------------------------------------------------------------------------------

// The centre of the ring of `sides` vertices from `first` on, posed at `seconds` and placed in the world.
glm::vec3 ringCentreAt(const Scene& scene, const std::string& name, double seconds, std::size_t first,
                       std::size_t sides) {
  const ScenePose pose = ScenePose::at(scene, seconds);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (scene.objects[i].name != name) continue;
    const std::vector<Vertex> posed =
        deformedVertices(scene.meshes[scene.objects[i].mesh], pose.morphWeights[i], pose.jointMatrices[i]);
    glm::vec3 sum(0.0f);
    for (std::size_t v = first; v < first + sides; ++v) sum += posed[v].position;
    return glm::vec3(pose.objectToWorld[i] * glm::vec4(sum / static_cast<float>(sides), 1.0f));
  }
  ADD_FAILURE() << "no object " << name;
  return glm::vec3(0.0f);
}

// skinned.glb (tests/data/gltf/make_gltf_scenes.py): the places below are worked from its joints and keys.
TEST_F(Importer, GltfSkinsPoseTheirMeshesByTheirJointsAtEveryTime) {
  Result<ImportedGltfScene> imported = importGltfScene(kGltfScenes / "skinned.glb");
  ASSERT_TRUE(imported.ok()) << imported.error();
  const Scene& scene = imported->scene;
  EXPECT_TRUE(scene.notes.empty()) << scene.notes.front();
  ASSERT_EQ(scene.rig.skinned.size(), 1u);
  ASSERT_EQ(scene.rig.skins.size(), 1u);
  EXPECT_EQ(scene.rig.skins[0].joints.size(), 2u);
  const std::size_t sides = 12, top = 16 * sides;
  // At rest the arm stands where it was bound, from (1.3, 0, 1.4) up 2 m: its node's translation is ignored.
  expectNear(ringCentreAt(scene, "arm", 0.0, 0, sides), {1.3f, 0.0f, 1.4f});
  expectNear(ringCentreAt(scene, "arm", 0.0, top, sides), {1.3f, 2.0f, 1.4f});
  // At 1 s the shoulder has turned 45° about y and the elbow bent 60° about z: the top, 1 m beyond the
  // elbow, is at Ry(45°)·((0, 1, 0) + Rz(60°)·(0, 1, 0)) from the shoulder.
  const float s = std::sin(glm::radians(60.0f)), c = std::cos(glm::radians(45.0f));
  expectNear(ringCentreAt(scene, "arm", 1.0, top, sides), {1.3f - s * c, 1.5f, 1.4f + s * c});
  // Below 0.75 m only the shoulder moves the arm: the base ring turns in place.
  expectNear(ringCentreAt(scene, "arm", 1.0, 0, sides), {1.3f, 0.0f, 1.4f});
  // The planner's box holds the arm at every time.
  const Mesh& arm = meshOf(scene, "arm");
  const DeformationExtents extents = deformationExtents(arm, 2);
  for (double t = 0.0; t < 2.0; t += 0.125) {
    const ScenePose pose = ScenePose::at(scene, t);
    const std::size_t i = static_cast<std::size_t>(objectNamed(scene, "arm") - scene.objects.data());
    const math::Bounds bounds = deformedBounds(extents, pose.morphWeights[i], pose.jointMatrices[i]);
    for (const Vertex& vertex : deformedVertices(arm, pose.morphWeights[i], pose.jointMatrices[i])) {
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(vertex.position, bounds.low - 1e-5f))) << t;
      EXPECT_TRUE(glm::all(glm::lessThanEqual(vertex.position, bounds.high + 1e-5f))) << t;
    }
  }
  // Unplayed, the arm is skinned once at rest into world space.
  GltfSceneChoice still;
  still.animation = "none";
  Result<ImportedGltfScene> baked = importGltfScene(kGltfScenes / "skinned.glb", still);
  ASSERT_TRUE(baked.ok()) << baked.error();
  EXPECT_TRUE(baked->scene.rig.skinned.empty());
  EXPECT_TRUE(meshOf(baked->scene, "arm").influences.empty());
  expectNear(meshOf(baked->scene, "arm").vertices[top].position, {1.3f + 0.2f, 2.0f, 1.4f});
}

// One triangle on node 0 skinned to node 1, which an animation moves: accessor 1 its joints (bytes),
// 2 its weights, 3 the inverse bind matrix, 4 key times (0, 1), 5 two translations.
json skinnedTriangle() {
  json document = triangleGltf();
  document["nodes"] = json::parse(R"([{"mesh": 0, "skin": 0}, {"translation": [0, 0, 0]}])");
  document["scenes"] = json::parse(R"([{"nodes": [0, 1]}])");
  document["skins"] = json::parse(R"([{"joints": [1], "inverseBindMatrices": 3}])");
  document["buffers"][0]["byteLength"] = 36 + 12 + 48 + 64 + 8 + 24;
  document["bufferViews"] =
      json::parse(R"([{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 12},
    {"buffer": 0, "byteOffset": 48, "byteLength": 48}, {"buffer": 0, "byteOffset": 96, "byteLength": 64},
    {"buffer": 0, "byteOffset": 160, "byteLength": 8}, {"buffer": 0, "byteOffset": 168, "byteLength": 24}])");
  document["accessors"].push_back({{"bufferView", 1}, {"componentType", 5121}, {"count", 3}, {"type", "VEC4"}});
  for (const auto& [view, type, count] : {std::tuple{2, "VEC4", 3}, {3, "MAT4", 1}, {4, "SCALAR", 2}, {5, "VEC3", 2}})
    document["accessors"].push_back({{"bufferView", view}, {"componentType", 5126}, {"count", count}, {"type", type}});
  document["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"] = 1;
  document["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = 2;
  document["animations"] = json::parse(R"([{"channels": [{"sampler": 0, "target": {"node": 1, "path": "translation"}}],
                                            "samplers": [{"input": 4, "output": 5}]}])");
  return document;
}

const std::string kSkinData = kTriangle + std::string(12, '\0') + floats({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}) +
                              floats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}) + floats({0, 1}) +
                              floats({0, 0, 0, 0, 2, 0});

TEST_F(Importer, GltfSkinsThatAreMalformedAreRefusedByTheirJsonPath) {
  Result<ImportedGltfScene> played = importGltfScene(write("asset.glb", glb(skinnedTriangle(), kSkinData)));
  ASSERT_TRUE(played.ok()) << played.error();
  ASSERT_EQ(played->scene.rig.skinned.size(), 1u);
  expectNear(ringCentreAt(played->scene, "node 0", 0.5, 1, 1), {1.0f, 1.0f, 0.0f});  // the joint rose 1 m by 0.5 s

  const auto expectRefused = [&](const std::function<void(json&)>& edit, const std::string& expected) {
    expectSceneRefused(skinnedTriangle(), kSkinData, edit, expected);
  };
  expectRefused([](json& d) { d["nodes"][0]["skin"] = 4; }, "$.nodes[0].skin: refers to skin 4, but the file has 1");
  expectRefused([](json& d) { d["skins"][0]["joints"][0] = 7; },
                "$.skins[0].joints[0]: refers to node 7, but the file has 2");
  expectRefused([](json& d) { d["skins"][0]["joints"] = json::array(); },
                "$.skins[0].joints: a skin needs at least one joint");
  expectRefused([](json& d) { d["scenes"][0]["nodes"] = json::array({0}); },
                "$.skins[0].joints[0]: node 1 is not in the scene drawn");
  expectRefused([](json& d) { d["skins"][0]["inverseBindMatrices"] = 4; },
                "accessor 4 ($.skins[0].inverseBindMatrices): has SCALAR elements, expected MAT4");
  expectRefused(
      [](json& d) {
        d["skins"][0]["joints"] = json::array({1, 1});
      },
      "($.skins[0].inverseBindMatrices): 1 matrices for 2 joints");
  expectRefused([](json& d) { d["meshes"][0]["primitives"][0]["attributes"].erase("WEIGHTS_0"); },
                "primitive 0 of mesh 0 has JOINTS_0 without WEIGHTS_0");
  expectRefused([](json& d) { d["accessors"][1]["componentType"] = 5126; },
                "(JOINTS_0 of primitive 0 of mesh 0): component type FLOAT is not allowed here");
  expectRefused(
      [](json& d) {
        d["meshes"][0]["primitives"][0]["attributes"].erase("WEIGHTS_0");
        d["meshes"][0]["primitives"][0]["attributes"].erase("JOINTS_0");
      },
      "$.nodes[0].skin: primitive 0 of mesh 0 has no JOINTS_0 and WEIGHTS_0");
}

TEST_F(Importer, AnimatedGlbMutationsNeverCrashAndAlwaysPoseFinitely) {
  for (const char* file : {"animated.glb", "morphing.glb", "skinned.glb"}) {
    const std::string original = readAll(kGltfScenes / file);
    std::uint32_t jsonLength = 0;
    std::memcpy(&jsonLength, original.data() + 12, 4);
    std::mt19937 random(5);
    int imported = 0;
    for (int round = 0; round < 1500; ++round) {
      std::string bytes = original;
      // Half the flips in the JSON, half in the animation data written last into the buffer.
      for (int flips = 1 + round % 3; flips > 0; --flips) {
        const std::size_t at = round % 2 == 0 ? 20 + random() % jsonLength : bytes.size() - 1 - random() % 600;
        bytes[at] = static_cast<char>(random() % 256);
      }
      Result<ImportedGltfScene> scene = importGltfScene(write(file, bytes));
      if (!scene.ok()) continue;
      ++imported;
      for (double t : {0.0, 0.7, 3.3}) {
        const ScenePose pose = ScenePose::at(scene->scene, t);
        for (const glm::mat4& m : pose.objectToWorld)
          for (int column = 0; column < 4; ++column)
            for (int row = 0; row < 4; ++row) ASSERT_TRUE(std::isfinite(m[column][row])) << file << " round " << round;
        ASSERT_EQ(math::cameraProblem(pose.camera), std::nullopt) << file << " round " << round;
        for (std::size_t i = 0; i < pose.morphWeights.size(); ++i) {
          if (pose.morphWeights[i].empty() && pose.jointMatrices[i].empty()) continue;
          const Mesh& mesh = scene->scene.meshes[scene->scene.objects[i].mesh];
          for (const Vertex& v : deformedVertices(mesh, pose.morphWeights[i], pose.jointMatrices[i]))
            ASSERT_TRUE(std::isfinite(v.position.x + v.position.y + v.position.z)) << file << " round " << round;
        }
      }
    }
    EXPECT_GT(imported, 100) << file << ": the mutations should leave many files readable";
  }
}

// The textured box: base colour textures from an external PNG, one per sampler the file pairs it with.
TEST_F(Importer, GltfSceneReadsBaseColourTexturesWithTheirSamplers) {
  Result<ImportedGltfScene> imported = importGltfScene(kGltfScenes / "textured-box.gltf");
  ASSERT_TRUE(imported.ok()) << imported.error();
  const Scene& scene = imported->scene;
  ASSERT_EQ(scene.textures.size(), 2u) << "crate.png clamped and mirrored: two textures";
  const SceneObject* crate = objectNamed(scene, "crate");
  const SceneObject* floor = objectNamed(scene, "floor");
  ASSERT_TRUE(crate && floor);
  const Material& crateMaterial = scene.materials[crate->material];
  ASSERT_TRUE(crateMaterial.texture.has_value());
  const Texture& crateTexture = scene.textures[*crateMaterial.texture];
  EXPECT_EQ(crateTexture.wrapU, TextureWrap::ClampToEdge);
  EXPECT_EQ(crateTexture.levels.front().width, 32);
  EXPECT_EQ(crateTexture.levels.size(), 6u);
  EXPECT_NE(crateTexture.name.find("crate.png"), std::string::npos) << crateTexture.name;
  ASSERT_TRUE(scene.materials[floor->material].texture.has_value());
  EXPECT_EQ(scene.textures[*scene.materials[floor->material].texture].wrapV, TextureWrap::MirroredRepeat);
  // Its uv came along: the crate's faces span [0, 1].
  float high = 0.0f;
  for (const Vertex& v : scene.meshes[crate->mesh].vertices) high = std::max(high, v.uv.x);
  EXPECT_FLOAT_EQ(high, 1.0f);
  EXPECT_TRUE(imported->scene.notes.empty());
}

TEST_F(Importer, GltfSceneRefusesBrokenTexturesByName) {
  const auto expectFailure = [&](const json& patch, const std::string& expected, const std::string& image = "") {
    json document = triangleGltf();
    document["nodes"] = json::parse(R"([{"mesh": 0}])");
    document["scenes"] = json::parse(R"([{"nodes": [0]}])");
    document["materials"] = json::parse(R"([{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])");
    document["meshes"][0]["primitives"][0]["material"] = 0;
    document.merge_patch(patch);
    if (!image.empty()) write("picture.png", image);
    Result<ImportedGltfScene> imported = importGltfScene(write("asset.glb", glb(document, kTriangle)));
    ASSERT_FALSE(imported.ok()) << expected;
    EXPECT_NE(imported.error().find(expected), std::string::npos)
        << "message: " << imported.error() << "\nlacks: " << expected;
  };
  const json picture = json::parse(R"({"images": [{"uri": "picture.png"}], "textures": [{"source": 0}]})");
  expectFailure(picture, "image 0 (picture.png): not an image this build reads", "words, not pixels");
  expectFailure(picture, "image 0 (picture.png): the image cannot be decoded",
                readAll(kGltfScenes / ".." / "scenes" / "bad" / "assets" / "truncated.png"));
  expectFailure(picture, "image 0 (picture.png): the image is 9000x16 texels",
                readAll(kGltfScenes / ".." / "scenes" / "bad" / "assets" / "huge.png"));
  expectFailure(json::parse(R"({"images": [{"uri": "../outside.png"}], "textures": [{"source": 0}]})"),
                "climbs out of");
  expectFailure(json::parse(R"({"textures": []})"),
                "material 0: baseColorTexture refers to texture 0, but the file has 0");
  json sampler = picture;
  sampler["textures"][0]["sampler"] = 3;
  expectFailure(sampler, "refers to sampler 3, but the file has 0", readAll(kGltfScenes / "crate.png"));
}

// The generated multi-part engine: every mesh node drawn, the deepest at its composed place.
TEST_F(Importer, GltfSceneDrawsAMultiPartModelWhole) {
  Result<ImportedGltfScene> imported = importGltfScene(kGltfScenes / "engine.glb");
  ASSERT_TRUE(imported.ok()) << imported.error();
  const Scene& scene = imported->scene;
  EXPECT_EQ(scene.objects.size(), 78u) << "82 nodes, 4 without a mesh (the root, the engine, two lights)";
  EXPECT_EQ(scene.mirrorCount(), 6u) << "two valve covers, two exhaust headers, the flywheel and the oil cap";
  EXPECT_EQ(scene.lights.size(), 2u);
  EXPECT_TRUE(imported->scene.notes.empty());
  // root > engine (matrix: up 1.2) > block (up 0.3) > left cylinder (-0.45, 0.8, 0) > left head (up 0.47)
  // > left spark plug (0.2, 0.2, 0) > left plug wire (up 0.08, turned about x): a torus about (-0.25, 3.05, 0).
  const SceneObject* wire = objectNamed(scene, "left plug wire");
  ASSERT_NE(wire, nullptr);
  math::Bounds bounds;
  for (const Vertex& v : scene.meshes[wire->mesh].vertices) bounds.add(v.position);
  expectNear(bounds.center(), {-0.25f, 3.05f, 0.0f});
  EXPECT_NEAR(bounds.high.z - bounds.low.z, 2.0f * 0.015f, 1e-4f) << "turned about x: the ring stands in the x-y plane";
}

TEST_F(Importer, GlbFramingMustHoldTogether) {
  const std::string good = glb(triangleGltf(), kTriangle);
  ASSERT_TRUE(gltf(good).ok());
  const auto expectFailure = [&](std::string bytes, const std::string& expected) {
    Result<Mesh> mesh = gltf(bytes);
    ASSERT_FALSE(mesh.ok()) << expected;
    EXPECT_NE(mesh.error().find(expected), std::string::npos) << "message: " << mesh.error() << "\nlacks: " << expected;
  };
  std::uint32_t jsonLength;
  std::memcpy(&jsonLength, good.data() + 12, 4);
  const std::size_t binStart = 20 + jsonLength;
  expectFailure(good.substr(0, 16), "truncated GLB: 16 bytes");
  expectFailure(good.substr(0, 4) + u32(1) + good.substr(8), "GLB container version 1");
  expectFailure(good.substr(0, good.size() - 4), "GLB header declares");
  expectFailure(good.substr(0, 12) + u32(0xFFFFFFF0u) + good.substr(16), "the GLB JSON chunk runs past the end");
  expectFailure(good.substr(0, 16) + "BIN" + good.substr(19), "the first GLB chunk is not the JSON chunk");
  // tinygltf 2.7 alone would accept a BIN chunk reaching 8 bytes past the end of the file.
  expectFailure(
      good.substr(0, binStart) + u32(static_cast<std::uint32_t>(good.size() - binStart)) + good.substr(binStart + 4),
      "the GLB BIN chunk runs past the end");
  expectFailure(good.substr(0, binStart + 4) + "JSON" + good.substr(binStart + 8),
                "the second GLB chunk is not the BIN chunk");
  expectFailure("glTF" + std::string(200, '\xff'), "GLB container version 4294967295");
}

TEST_F(Importer, GltfAccessorsMustLieInsideTheirBuffers) {
  expectGltfFailure(
      [](json& d) { d["accessors"][0]["count"] = 4; },
      "accessor 0 (POSITION of primitive 0 of mesh 0): 4 elements of 12 bytes (stride 12, offset 0) overrun "
      "buffer view 0 (36 bytes)");
  expectGltfFailure([](json& d) { d["accessors"][0]["byteOffset"] = std::uint64_t{1} << 62; }, "overrun buffer view 0");
  expectGltfFailure([](json& d) { d["accessors"][0]["count"] = std::uint64_t{1} << 40; },
                    "has 1099511627776 elements, more than the limit of 8388608");
  expectGltfFailure([](json& d) { d["bufferViews"][0]["byteLength"] = 1000; },
                    "buffer view 0 (1000 bytes at offset 0) lies outside buffer 0 (36 bytes)");
  expectGltfFailure([](json& d) { d["bufferViews"][0]["byteOffset"] = std::uint64_t{1} << 63; },
                    "lies outside buffer 0");
  expectGltfFailure([](json& d) { d["bufferViews"][0]["byteStride"] = 4; },
                    "byte stride of 4, less than the 12-byte element");
  expectGltfFailure([](json& d) { d["accessors"][0]["bufferView"] = 7; },
                    "refers to buffer view 7, but the file has 1");
  expectGltfFailure([](json& d) { d["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 9; },
                    "POSITION of primitive 0 of mesh 0 refers to accessor 9, but the file has 1");
}

TEST_F(Importer, GltfAccessorsMustHaveTheRightShape) {
  expectGltfFailure([](json& d) { d["accessors"][0]["componentType"] = 5123; },
                    "component type UNSIGNED_SHORT is not allowed here (allowed: FLOAT)");
  expectGltfFailure([](json& d) { d["accessors"][0]["type"] = "VEC2"; }, "has VEC2 elements, expected VEC3");
  expectGltfFailure(
      [](json& d) {
        d["accessors"][0]["sparse"] = json::parse(
            R"({"count": 1, "indices": {"bufferView": 0, "componentType": 5125}, "values": {"bufferView": 0}})");
      },
      "sparse accessors are not supported");
  expectGltfFailure([](json& d) { d["meshes"][0]["primitives"][0]["attributes"].erase("POSITION"); },
                    "primitive 0 of mesh 0 has no POSITION attribute");
  expectGltfFailure([](json& d) { d["meshes"][0]["primitives"][0]["mode"] = 5; },
                    "has mode 5; only triangle lists (mode 4) are supported");
  expectGltfFailure([](json& d) { d["meshes"][0]["primitives"] = json::array(); }, "mesh 0 has no primitives");
  expectGltfFailure([](json& d) { d.erase("meshes"); }, "the file holds no meshes");
}

TEST_F(Importer, GltfAttributesAndIndicesMustBeSound) {
  const std::string triangleAndMore = kTriangle + floats({0, 0, 1, 0, 0, 1, 0, 0, 0}) + std::string("\0\1\5\0", 4);
  const auto withExtras = [](json& d) {
    d["buffers"][0]["byteLength"] = 76;
    d["bufferViews"].push_back(json::parse(R"({"buffer": 0, "byteOffset": 36, "byteLength": 36})"));
    d["bufferViews"].push_back(json::parse(R"({"buffer": 0, "byteOffset": 72, "byteLength": 3})"));
    d["accessors"].push_back(json::parse(R"({"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"})"));
    d["accessors"].push_back(json::parse(R"({"bufferView": 2, "componentType": 5121, "count": 3, "type": "SCALAR"})"));
  };
  expectGltfFailure(
      [&](json& d) {
        withExtras(d);
        d["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 1;
      },
      "accessor 1 (NORMAL of primitive 0 of mesh 0): element 2 is a zero vector", triangleAndMore);
  expectGltfFailure(
      [&](json& d) {
        withExtras(d);
        d["meshes"][0]["primitives"][0]["indices"] = 2;
      },
      "accessor 2 (indices of primitive 0 of mesh 0): index 2 is 5, but POSITION has 3 vertices", triangleAndMore);
  expectGltfFailure(
      [&](json& d) {
        withExtras(d);
        d["accessors"][2]["count"] = 2;
        d["meshes"][0]["primitives"][0]["indices"] = 2;
      },
      "has 2 indices, not a multiple of 3", triangleAndMore);
  expectGltfFailure(
      [&](json& d) {
        withExtras(d);
        d["accessors"][1]["count"] = 2;
        d["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 1;
      },
      "has 2 elements but POSITION has 3", triangleAndMore);
  expectGltfFailure(
      [&](json& d) {
        withExtras(d);
        d["accessors"][2]["type"] = "VEC2";
        d["accessors"][2]["count"] = 1;
        d["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 2;
      },
      "integer attributes must be normalized", triangleAndMore);
  expectGltfFailure([](json&) {}, "element 1 is not finite", floats({0, 0, 0, NAN, 0, 0, 0, 1, 0}));
  expectGltfFailure([](json& d) { d["accessors"][0]["count"] = 2; },
                    "has no indices and 2 vertices, not a multiple of 3");
}

TEST_F(Importer, GltfBuffersAndUrisStayBoundedAndInsideTheFolder) {
  expectGltfFailure([](json& d) { d["buffers"][0]["byteLength"] = std::uint64_t{1} << 40; },
                    "buffer 0: buffers declare more than 268435456 bytes in all");
  expectGltfFailure(
      [](json& d) {
        // Each buffer without a URI would get its own copy of the BIN chunk.
        d["buffers"] = json::array();
        for (int i = 0; i < 9; ++i) d["buffers"].push_back({{"byteLength", 32u << 20}});
      },
      "buffer 8: buffers declare more than");
  expectGltfFailure([](json& d) { d["buffers"][0]["byteLength"] = -36; },
                    "buffer 0: byteLength must be a positive integer");
  const auto withUri = [](std::string uri) { return [uri](json& d) { d["buffers"][0]["uri"] = uri; }; };
  expectGltfFailure(withUri("../outside.bin"), "climbs out of");
  expectGltfFailure(withUri("/etc/passwd"), "is absolute");
  expectGltfFailure(withUri("http://example.com/tri.bin"), "is a URI");
  ASSERT_EQ(::mkfifo((dir_ / "pipe.bin").c_str(), 0600), 0);
  expectGltfFailure(withUri("pipe.bin"), "is not a regular file");  // and must not block reading it
  write("tri.bin", kTriangle);
  json document = triangleGltf();
  document["buffers"][0]["uri"] = "tri.bin";
  Result<Mesh> external = importGltf(write("tri.gltf", document.dump()), {}, "m");
  EXPECT_TRUE(external.ok()) << external.error();
}

TEST_F(Importer, GltfJsonIsParsedStrictlyBeforeTinyGltfSeesIt) {
  expectGltfFailure([](json& d) { d["extras"] = json::parse(std::string(500, '[') + std::string(500, ']')); },
                    "nested deeper than 64 levels");
  Result<Mesh> duplicate = gltf(R"({"asset": {"version": "2.0"}, "asset": {"version": "2.0"}})");
  ASSERT_FALSE(duplicate.ok());
  EXPECT_NE(duplicate.error().find("$.asset: duplicate key"), std::string::npos) << duplicate.error();
  Result<Mesh> notJson = gltf("solid cube\nfacet normal 0 0 1\n");
  ASSERT_FALSE(notJson.ok());
  EXPECT_NE(notJson.error().find("invalid JSON"), std::string::npos) << notJson.error();
  Result<Mesh> empty = gltf("");
  ASSERT_FALSE(empty.ok());
  EXPECT_NE(empty.error().find("empty file"), std::string::npos) << empty.error();
}

TEST_F(Importer, EveryTruncationOfAGoodAssetFailsCleanly) {
  for (const char* name : {"wedge.glb", "quad.gltf"}) {
    const std::string bytes = readAll(kAssets / name);
    // Cutting only trailing whitespace off the JSON file leaves it intact.
    for (std::size_t length = 0; length <= bytes.find_last_not_of(" \n"); ++length) {
      Result<Mesh> mesh = importGltf(write(name, bytes.substr(0, length)), std::size_t{0}, "m");
      EXPECT_FALSE(mesh.ok()) << name << " cut to " << length << " bytes imported";
    }
  }
}

TEST_F(Importer, GlbMutationsNeverCrashAndYieldOnlySoundMeshes) {
  const std::string original = readAll(kAssets / "wedge.glb");
  std::mt19937 random(3);
  for (int round = 0; round < 2000; ++round) {
    std::string bytes = original;
    for (int flips = 1 + round % 4; flips > 0; --flips)
      bytes[random() % bytes.size()] = static_cast<char>(random() % 256);
    Result<Mesh> mesh = gltf(bytes);
    if (mesh.ok()) expectValidMesh(mesh.value());
  }
}

// ---- shared pieces ---------------------------------------------------------------------------------

TEST_F(Importer, ReadBoundedFileRefusesOversizedAndNonRegularFiles) {
  const fs::path file = write("ten.txt", "0123456789");
  EXPECT_EQ(readBoundedFile(file, 10).value(), "0123456789");
  Result<std::string> big = readBoundedFile(file, 9);
  ASSERT_FALSE(big.ok());
  EXPECT_EQ(big.error(), file.string() + ": 10 bytes, more than the limit of 9");
  EXPECT_EQ(readBoundedFile(dir_ / "none", 9).error(), (dir_ / "none").string() + ": no such file");
  EXPECT_EQ(readBoundedFile(dir_, 9).error(), dir_.string() + ": is a directory, not a file");
  EXPECT_EQ(readBoundedFile("/dev/zero", 9).error(), "/dev/zero: is not a regular file");
}

TEST(AssetFiles, ResolveInsideKeepsPathsWithinTheFolder) {
  EXPECT_EQ(resolveInside("scenes", "assets/./a.obj").value(), fs::path("scenes/assets/a.obj"));
  EXPECT_EQ(resolveInside("scenes", "assets/../a.obj").value(), fs::path("scenes/a.obj"));
  EXPECT_FALSE(resolveInside("scenes", "assets/../../a.obj").ok());
  EXPECT_FALSE(resolveInside("scenes", "/a.obj").ok());
  EXPECT_FALSE(resolveInside("scenes", "").ok());
  EXPECT_FALSE(resolveInside("scenes", "file:///a.obj").ok());
  EXPECT_FALSE(resolveInside("scenes", std::string_view("a\0/../../b", 10)).ok());
}

TEST(MeshNormals, SmoothNormalsAreSharedByVerticesAtOnePosition) {
  // Two triangles folded along the x axis, their shared edge duplicated as a uv seam would.
  Mesh mesh;
  mesh.vertices = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 0, -1}}, {{0, 0, 0}}, {{0, -1, 0}}, {{1, 0, 0}}};
  mesh.indices = {0, 1, 2, 3, 4, 5};
  computeSmoothNormals(mesh);
  expectNear(mesh.vertices[0].normal, glm::normalize(glm::vec3(0, 1, 1)));
  expectNear(mesh.vertices[3].normal, mesh.vertices[0].normal);
  expectNear(mesh.vertices[2].normal, {0, 1, 0});
  expectNear(mesh.vertices[4].normal, {0, 0, 1});
}

TEST(MeshNormals, FlatShadingGivesEachTriangleItsOwnVerticesAndFaceNormal) {
  Mesh mesh;
  mesh.vertices = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}};
  mesh.indices = {0, 1, 2, 0, 3, 1};
  makeFlatShaded(mesh);
  ASSERT_EQ(mesh.vertices.size(), 6u);
  EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
  for (int i = 0; i < 3; ++i) expectNear(mesh.vertices[static_cast<std::size_t>(i)].normal, {0, 0, 1});
  for (int i = 3; i < 6; ++i) expectNear(mesh.vertices[static_cast<std::size_t>(i)].normal, {0, 1, 0});
}
