#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "math/Color.h"
#include "scene/AssetFiles.h"
#include "scene/SceneChecks.h"
#include "scene/SceneLoader.h"
#include "scene/ScenePose.h"
#include "scene/StrictJson.h"

using namespace specula;
using namespace specula::scene;
namespace fs = std::filesystem;

namespace {

const fs::path kScenes = fs::path(SPECULA_TEST_DATA_DIR) / "scenes";

std::vector<fs::path> sceneFiles(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string testName(const testing::TestParamInfo<fs::path>& info) {
  std::string name = info.param.stem().string();
  std::replace_if(
      name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
}

// The expected parts of a bad file's error message: the non-empty lines of its ".expect" sidecar.
std::vector<std::string> expectedMessageParts(const fs::path& sceneFile) {
  std::ifstream in(fs::path(sceneFile).replace_extension(".expect"));
  std::vector<std::string> parts;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) parts.push_back(line);
  return parts;
}

const Mesh& meshOf(const Scene& scene, const std::string& objectName) {
  const auto it = std::find_if(scene.objects.begin(), scene.objects.end(),
                               [&](const SceneObject& o) { return o.name == objectName; });
  EXPECT_NE(it, scene.objects.end()) << objectName;
  return scene.meshes[it->mesh];
}

const SceneObject& objectNamed(const Scene& scene, const std::string& name) {
  return *std::find_if(scene.objects.begin(), scene.objects.end(),
                       [&](const SceneObject& o) { return o.name == name; });
}

// A small valid scene with `extra` spliced in as further top-level members.
std::string sceneWith(const std::string& extra) {
  return R"({"specula_scene": 1, "camera": {"eye": [0, 0, 5], "target": [0, 0, 0]},
             "meshes": [{"name": "m", "primitive": {"type": "box", "size": [1, 1, 1]}}],
             "materials": [{"name": "a", "color": "#ffffff"}],
             "objects": [{"name": "o", "mesh": "m", "material": "a"}])" +
         extra + "}";
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

}  // namespace

class GoodSceneFile : public testing::TestWithParam<fs::path> {};

TEST_P(GoodSceneFile, LoadsPassesSceneChecksAndPosesAtAnyTime) {
  Result<Scene> scene = loadSceneFile(GetParam());
  ASSERT_TRUE(scene.ok()) << scene.error();
  EXPECT_FALSE(sceneProblem(scene.value()).has_value());
  for (double seconds : {0.0, 1.25, 4.0, 1000.0}) {
    const ScenePose pose = ScenePose::at(scene.value(), seconds);
    EXPECT_EQ(pose.objectToWorld.size(), scene->objects.size());
    EXPECT_FALSE(math::cameraProblem(pose.camera).has_value());
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, GoodSceneFile, testing::ValuesIn(sceneFiles(kScenes / "good")), testName);

class BadSceneFile : public testing::TestWithParam<fs::path> {};

TEST_P(BadSceneFile, FailsWithMessageNamingTheFileAndTheExpectedProblem) {
  const std::vector<std::string> parts = expectedMessageParts(GetParam());
  ASSERT_FALSE(parts.empty()) << "add " << fs::path(GetParam()).replace_extension(".expect")
                              << " listing parts of the expected message, one per line";
  Result<Scene> scene = loadSceneFile(GetParam());
  ASSERT_FALSE(scene.ok()) << GetParam() << " loaded, but it should fail";
  EXPECT_TRUE(scene.error().starts_with(GetParam().string() + ": ")) << scene.error();
  for (const std::string& part : parts)
    EXPECT_NE(scene.error().find(part), std::string::npos) << "message: " << scene.error() << "\nlacks: " << part;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadSceneFile, testing::ValuesIn(sceneFiles(kScenes / "bad")), testName);

TEST(SceneLoader, CorporaHoldTheRequiredFiles) {
  EXPECT_GE(sceneFiles(kScenes / "good").size(), 3u);
  EXPECT_GE(sceneFiles(kScenes / "bad").size(), 20u);
}

TEST(SceneLoader, CheckerSphereFileReproducesTheReferenceScene) {
  Result<Scene> loaded = loadSceneFile(kScenes / "good" / "checker-sphere.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  const Scene& scene = loaded.value();
  expectNear(scene.camera.eye, {1.0f, 3.0f, 3.5f});
  expectNear(scene.camera.target, {0.0f, -0.3f, 0.0f});
  EXPECT_FLOAT_EQ(scene.camera.fovYDegrees, 40.0f);
  expectNear(scene.background, glm::vec3(0.0f));

  const SceneObject& sphere = objectNamed(scene, "mirror-sphere");
  ASSERT_TRUE(sphere.mirror.has_value());
  EXPECT_EQ(sphere.mirror->curvature, MirrorCurvature::Convex);
  EXPECT_TRUE(sphere.mirror->closed);
  ASSERT_TRUE(sphere.mirror->analytic.has_value());
  EXPECT_EQ(sphere.mirror->analytic->kind, AnalyticShape::Kind::Sphere);
  expectNear(sphere.mirror->analytic->radii, glm::vec3(1.0f));
  expectNear(sphere.transform.translation, glm::vec3(0.0f));
  EXPECT_FLOAT_EQ(scene.materials[sphere.material].reflectivity, 1.0f);
  expectNear(scene.materials[sphere.material].baseColor, glm::vec3(0.0f));
  for (const Vertex& v : meshOf(scene, "mirror-sphere").vertices) EXPECT_NEAR(glm::length(v.position), 1.0f, 1e-5f);

  const SceneObject& floor = objectNamed(scene, "floor");
  expectNear(floor.transform.translation, {0.0f, -1.0f, 0.0f});
  const Mesh& grid = meshOf(scene, "floor");
  EXPECT_EQ(grid.triangleCount(), 16u * 16u * 2u);
  for (const Vertex& v : grid.vertices) {
    EXPECT_LE(std::abs(v.position.x), 8.0f + 1e-5f);
    EXPECT_LE(std::abs(v.position.z), 8.0f + 1e-5f);
  }
  const Material& checker = scene.materials[floor.material];
  EXPECT_TRUE(checker.unlit);
  ASSERT_TRUE(checker.checker.has_value());
  expectNear(checker.baseColor, glm::vec3(math::srgbToLinear(230.0f / 255.0f)));
  expectNear(checker.checker->oddColor, glm::vec3(math::srgbToLinear(25.0f / 255.0f)));
  EXPECT_FLOAT_EQ(checker.checker->cellsPerUnit, 1.0f);
}

TEST(SceneLoader, EveryFeatureFileFillsEveryPartOfTheModel) {
  Result<Scene> loaded = loadSceneFile(kScenes / "good" / "every-feature.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  const Scene& scene = loaded.value();
  EXPECT_EQ(scene.name, "every feature");
  EXPECT_EQ(scene.meshes.size(), 11u);
  EXPECT_EQ(scene.materials.size(), 3u);
  EXPECT_EQ(scene.objects.size(), 11u);
  expectNear(scene.background, math::srgbToLinear(glm::vec3(0.1f, 0.2f, 0.3f)));
  expectNear(scene.ambient, glm::vec3(math::srgbToLinear(32.0f / 255.0f)));

  EXPECT_EQ(meshOf(scene, "pyramid").triangleCount(), 6u);  // four sides and a fan-split base
  EXPECT_EQ(meshOf(scene, "quad").triangleCount(), 2u);
  EXPECT_EQ(meshOf(scene, "triangle").vertices.size(), 3u);
  EXPECT_EQ(meshOf(scene, "wedge").vertices.size(), 6u);  // no normals in the file: flat-shaded

  const SceneObject& pipe = objectNamed(scene, "pipe");
  ASSERT_TRUE(pipe.mirror.has_value());
  EXPECT_FALSE(pipe.mirror->closed);
  EXPECT_EQ(scene.meshes[pipe.mirror->closedTwinMesh.value()].name, "can-closed");
  EXPECT_EQ(pipe.mirror->curvature, MirrorCurvature::Concave);
  const glm::quat quarterTurn = glm::angleAxis(glm::radians(90.0f), glm::vec3(1, 0, 0));
  EXPECT_NEAR(std::abs(glm::dot(pipe.transform.rotation, quarterTurn)), 1.0f, 1e-6f);

  const SceneObject& egg = objectNamed(scene, "egg");
  EXPECT_EQ(egg.mirror->analytic->kind, AnalyticShape::Kind::Ellipsoid);
  expectNear(egg.mirror->analytic->radii, {1.0f, 1.5f, 1.0f});
  expectNear(egg.transform.scale, {1.0f, 1.5f, 1.0f});
  expectNear(objectNamed(scene, "crate").transform.scale, glm::vec3(0.5f));
  EXPECT_FALSE(objectNamed(scene, "crate").reflected);
  EXPECT_NEAR(glm::length(objectNamed(scene, "ring").transform.rotation), 1.0f, 1e-6f);

  ASSERT_EQ(scene.lights.size(), 3u);
  EXPECT_EQ(scene.lights[0].kind, Light::Kind::Directional);
  expectNear(scene.lights[0].vector, glm::normalize(glm::vec3(1, 2, 1)));
  EXPECT_EQ(scene.lights[1].kind, Light::Kind::Point);
  expectNear(scene.lights[1].vector, {0.0f, 5.0f, 0.0f});
  EXPECT_FLOAT_EQ(scene.lights[2].intensity, 1.0f);

  ASSERT_EQ(scene.animations.size(), 4u);
  const auto& spin = std::get<Spin>(scene.animations[0].motion);
  expectNear(spin.axis, {0.0f, 1.0f, 0.0f});  // given as [0, 2, 0]
  const auto& path = std::get<TransformPath>(scene.animations[2].motion);
  EXPECT_FALSE(path.loop);
  ASSERT_EQ(path.keys.size(), 3u);
  // Parts a key leaves out come from the object's rest transform.
  expectNear(path.keys[2].transform.translation, {0.0f, 3.0f, -4.0f});
  expectNear(path.keys[2].transform.scale, {1.0f, 2.0f, 1.0f});
  const auto& cameraPath = std::get<CameraPath>(scene.animations[3].motion);
  EXPECT_FALSE(scene.animations[3].object.has_value());
  EXPECT_FLOAT_EQ(cameraPath.keys[0].camera.fovYDegrees, 50.0f);  // from the scene camera
  EXPECT_FLOAT_EQ(cameraPath.keys[1].camera.fovYDegrees, 35.0f);
}

TEST(SceneLoader, MinimalFileTakesDocumentedDefaults) {
  Result<Scene> loaded = loadSceneFile(kScenes / "good" / "minimal.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  const Scene& scene = loaded.value();
  EXPECT_EQ(scene.name, "minimal");  // the file name without extension
  EXPECT_FLOAT_EQ(scene.camera.fovYDegrees, 45.0f);
  expectNear(scene.camera.up, {0.0f, 1.0f, 0.0f});
  expectNear(scene.ambient, Scene{}.ambient);
  expectNear(scene.background, glm::vec3(0.0f));
  EXPECT_TRUE(scene.lights.empty());
  EXPECT_TRUE(scene.animations.empty());
  EXPECT_FLOAT_EQ(scene.materials[0].reflectivity, 0.0f);
  EXPECT_FALSE(scene.materials[0].unlit);
  EXPECT_TRUE(scene.objects[0].reflected);
  EXPECT_FALSE(scene.objects[0].mirror.has_value());
}

TEST(SceneLoader, ConvertsHexAndArrayColoursFromSrgbToLinear) {
  Result<Scene> scene = parseScene(sceneWith(R"(, "background": "#FF8000", "ambient": [0.5, 0.25, 1])"), ".", "inline");
  ASSERT_TRUE(scene.ok()) << scene.error();
  expectNear(scene->background, {1.0f, math::srgbToLinear(128.0f / 255.0f), 0.0f});
  expectNear(scene->ambient, math::srgbToLinear(glm::vec3(0.5f, 0.25f, 1.0f)));
}

TEST(SceneLoader, PrefixesErrorsWithTheSourceNameGivenToParseScene) {
  Result<Scene> scene = parseScene(sceneWith(R"(, "lights": [{"type": "point"}])"), ".", "uploaded scene");
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.error(), R"(uploaded scene: $.lights[0]: missing required key "position")");
}

TEST(SceneLoader, ResolvesMeshFilesAgainstTheBaseFolder) {
  const std::string json = R"({"specula_scene": 1, "camera": {"eye": [0, 0, 5], "target": [0, 0, 0]},
    "meshes": [{"name": "p", "file": "assets/pyramid.obj"}], "materials": [{"name": "a", "color": "#ffffff"}],
    "objects": [{"name": "o", "mesh": "p", "material": "a"}]})";
  EXPECT_TRUE(parseScene(json, kScenes / "good", "inline").ok());
  Result<Scene> elsewhere = parseScene(json, kScenes / "bad", "inline");
  ASSERT_FALSE(elsewhere.ok());
  EXPECT_NE(elsewhere.error().find("inline: $.meshes[0].file: "), std::string::npos) << elsewhere.error();
  EXPECT_NE(elsewhere.error().find("no such file"), std::string::npos) << elsewhere.error();
}

TEST(SceneLoader, WritesOddKeysAsBracketedStringsInPaths) {
  Result<Scene> scene = parseScene(sceneWith(R"(, "back ground": "#000000")"), ".", "inline");
  ASSERT_FALSE(scene.ok());
  EXPECT_NE(scene.error().find(R"(inline: $["back ground"]: unknown key)"), std::string::npos) << scene.error();
}

TEST(SceneLoader, ReportsAMissingSceneFileByName) {
  Result<Scene> scene = loadSceneFile(kScenes / "no-such-scene.json");
  ASSERT_FALSE(scene.ok());
  EXPECT_NE(scene.error().find("no-such-scene.json: no such file"), std::string::npos) << scene.error();
}

TEST(SceneLoader, RefusesSceneTextOverTheSizeLimit) {
  const std::string huge(kMaxSceneFileBytes + 1, ' ');
  Result<Scene> scene = parseScene(huge, ".", "huge.json");
  ASSERT_FALSE(scene.ok());
  EXPECT_NE(scene.error().find("huge.json: 67108865 bytes, more than the limit"), std::string::npos) << scene.error();
}

TEST(SceneLoader, NormalizesAxesQuaternionsAndDirections) {
  Result<Scene> scene = parseScene(sceneWith(R"(,
      "lights": [{"type": "directional", "direction": [0, 0, -3]}],
      "animations": [{"target": "o", "orbit": {"axis": [0, 0, 5], "degrees_per_second": 1}},
                     {"target": "o", "path": {"keys": [{"time": 0, "rotation": {"quaternion": [0, 0, 0, 2]}}]}}])"),
                                   ".", "inline");
  ASSERT_TRUE(scene.ok()) << scene.error();
  expectNear(scene->lights[0].vector, {0.0f, 0.0f, -1.0f});
  expectNear(std::get<Orbit>(scene->animations[0].motion).axis, {0.0f, 0.0f, 1.0f});
  const glm::quat q = std::get<TransformPath>(scene->animations[1].motion).keys[0].transform.rotation;
  EXPECT_FLOAT_EQ(q.w, 1.0f);
}

TEST(StrictJson, NamesThePathOfADuplicateKeyAfterNestedContainers) {
  Result<nlohmann::json> document =
      parseStrictJson(R"({"objects": [{"a": {"b": [1, [2, 3]]}, "c": [4]}, {"name": "x", "name": "y"}]})");
  ASSERT_FALSE(document.ok());
  EXPECT_EQ(document.error(), "$.objects[1].name: duplicate key; each key may appear once per object");
}

TEST(StrictJson, AcceptsTheDeepestAllowedNestingAndRefusesOneMore) {
  const auto nested = [](std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); };
  EXPECT_TRUE(parseStrictJson(nested(kMaxJsonDepth)).ok());
  Result<nlohmann::json> tooDeep = parseStrictJson(nested(kMaxJsonDepth + 1));
  ASSERT_FALSE(tooDeep.ok());
  EXPECT_NE(tooDeep.error().find("nested deeper than 64 levels"), std::string::npos) << tooDeep.error();
}

TEST(StrictJson, RefusesNonFiniteNumbersWithTheirPath) {
  Result<nlohmann::json> document = parseStrictJson(R"({"a": [0, -1e400]})");
  ASSERT_FALSE(document.ok());
  EXPECT_NE(document.error().find("$.a[1]: number out of range"), std::string::npos) << document.error();
}

TEST(StrictJson, ReportsSyntaxErrorsWithLineAndColumn) {
  Result<nlohmann::json> document = parseStrictJson("{\n  \"a\": [1, 2,\n}");
  ASSERT_FALSE(document.ok());
  EXPECT_NE(document.error().find("invalid JSON: parse error at line 3, column 1"), std::string::npos)
      << document.error();
}

namespace specula::scene {
namespace {

// Numbers JSON cannot hold exactly: overflow to infinity, or NaN spelled out. Each must be refused at
// load with a message naming where, never reach a renderer.
TEST(SceneLoader, RejectsNonFiniteNumbersAtLoad) {
  const std::vector<std::string> bad = {
      R"({"specula_scene": 1, "camera": {"eye": [0, 0, 1e999], "target": [0, 0, 0]},
          "meshes": [{"name": "m", "primitive": {"type": "box", "size": [1, 1, 1]}}],
          "materials": [{"name": "a", "color": "#ffffff"}], "objects": [{"name": "o", "mesh": "m", "material": "a"}]})",
      R"({"specula_scene": 1, "camera": {"eye": [0, 0, 5], "target": [0, 0, 0]},
          "meshes": [{"name": "m", "primitive": {"type": "box", "size": [1, -1e999, 1]}}],
          "materials": [{"name": "a", "color": "#ffffff"}], "objects": [{"name": "o", "mesh": "m", "material": "a"}]})",
      R"({"specula_scene": 1, "camera": {"eye": [0, 0, 5], "target": [0, 0, 0]},
          "meshes": [{"name": "m", "primitive": {"type": "box", "size": [1, 1, 1]}}],
          "materials": [{"name": "a", "color": "#ffffff"}],
          "objects": [{"name": "o", "mesh": "m", "material": "a", "position": [NaN, 0, 0]}]})",
      R"({"specula_scene": 1, "camera": {"eye": [0, 0, 5], "target": [0, 0, 0]},
          "meshes": [{"name": "m", "primitive": {"type": "box", "size": [1, 1, 1]}}],
          "materials": [{"name": "a", "color": "#ffffff"}],
          "objects": [{"name": "o", "mesh": "m", "material": "a", "position": [1e39, 0, 0]}]})",
  };
  for (const std::string& json : bad) {
    Result<Scene> scene = parseScene(json, ".", "inline");
    EXPECT_FALSE(scene.ok()) << json;
    if (!scene.ok()) {
      EXPECT_NE(scene.error().find("inline"), std::string::npos) << scene.error();
    }
  }
}

}  // namespace
}  // namespace specula::scene

// A scene file that includes glTF scenes as groups: their objects are named "<group>/<object>" for
// animations and overrides, placed by the group's transform, with their materials and textures.
TEST(SceneLoader, IncludedGltfScenesAreGroupsWithNamedObjects) {
  Result<Scene> scene = loadSceneFile(fs::path(SPECULA_TEST_DATA_DIR) / "gltf" / "includes.json");
  ASSERT_TRUE(scene.ok()) << scene.error();
  std::vector<std::string> names;
  for (const SceneObject& object : scene->objects) names.push_back(object.name);
  EXPECT_EQ(names, (std::vector<std::string>{"ground", "left/crate", "left/floor", "right/crate", "right/floor",
                                             "ball/sphere", "ball/floor", "ball/red box", "ball/green box"}));
  const SceneObject& right = scene->objects[3];
  EXPECT_FLOAT_EQ(right.transform.scale.x, 0.5f);
  EXPECT_FLOAT_EQ(right.transform.translation.x, 3.0f);
  EXPECT_TRUE(scene->objects[5].mirror.has_value()) << "the chrome sphere stays a mirror";
  ASSERT_TRUE(scene->materials[right.material].texture.has_value());
  EXPECT_LT(*scene->materials[right.material].texture, scene->textures.size());
  EXPECT_EQ(scene->materials[right.material].name, "right/crate");
  ASSERT_EQ(scene->animations.size(), 1u);
  EXPECT_EQ(scene->animations[0].object, std::optional<std::uint32_t>(1u)) << "the spin moves left/crate";
  ASSERT_EQ(scene->lights.size(), 1u) << "the file's lights, not the included files'";
  EXPECT_FALSE(sceneProblem(*scene).has_value());
  // The group moves its objects: left/crate's box is centred 3 m to the left of the included file's.
  const ScenePose pose = ScenePose::at(*scene, 0.0);
  EXPECT_FLOAT_EQ(pose.objectToWorld[1][3].x, -3.0f);
}

// An include plays the animations it names, placed where the include puts the group; the file's own
// camera stays, though the glTF's camera node has an animation of its own.
// An open mirror without a closed twin to search is two-sided and ray-cast, as open glTF chrome meshes are.
TEST(SceneLoader, AnOpenMirrorWithoutATwinIsTwoSided) {
  Result<Scene> scene = parseScene(R"({"specula_scene": 1, "camera": {"eye": [0, 2, 6], "target": [0, 0, 0]},
    "meshes": [{"name": "pipe", "primitive": {"type": "cylinder", "radius": 1, "height": 2, "capped": false}}],
    "materials": [{"name": "chrome", "color": "#000000", "reflectivity": 1}],
    "objects": [{"name": "pipe", "mesh": "pipe", "material": "chrome", "mirror": {"closed": false}}]})",
                                   ".", "inline");
  ASSERT_TRUE(scene.ok()) << scene.error();
  ASSERT_TRUE(scene->objects[0].mirror.has_value());
  EXPECT_TRUE(scene->objects[0].mirror->twoSided());
  EXPECT_FALSE(sceneProblem(*scene).has_value());
}

TEST(SceneLoader, AnIncludePlaysItsChosenAnimationsWhereItIsPlaced) {
  Result<Scene> scene = loadSceneFile(fs::path(SPECULA_TEST_DATA_DIR) / "gltf" / "animated-includes.json");
  ASSERT_TRUE(scene.ok()) << scene.error();
  ASSERT_FALSE(sceneProblem(*scene).has_value());
  EXPECT_TRUE(scene->moves());
  ASSERT_EQ(scene->rig.clips.size(), 1u);
  EXPECT_EQ(scene->rig.clips[0].name, "moving/show");
  const auto originAt = [&](const std::string& name, double seconds) {
    const ScenePose pose = ScenePose::at(*scene, seconds);
    for (std::size_t i = 0; i < scene->objects.size(); ++i)
      if (scene->objects[i].name == name) return glm::vec3(pose.objectToWorld[i] * glm::vec4(0, 0, 0, 1));
    ADD_FAILURE() << "no object " << name;
    return glm::vec3(0.0f);
  };
  // At 0.25 s the carousel has carried the red box 45° round, to (c, 0.4, -c); the include turns that a
  // quarter about y, to (-c, 0.4, -c), and moves it 6 along x.
  const float c = 2.5f * std::cos(glm::radians(45.0f));
  const glm::vec3 moving = originAt("moving/red box", 0.25);
  EXPECT_NEAR(moving.x, 6.0f - c, 1e-5f);
  EXPECT_NEAR(moving.y, 0.4f, 1e-5f);
  EXPECT_NEAR(moving.z, -c, 1e-5f);
  for (double t : {0.0, 0.25, 1.0})  // baked into the glTF's world space at rest, placed by the include
    EXPECT_EQ(originAt("still/red box", t), glm::vec3(-6.0f, 0.0f, 0.0f));
  const ScenePose later = ScenePose::at(*scene, 2.0);
  EXPECT_EQ(later.camera.eye, scene->camera.eye) << "an include's camera animation does not move the file's camera";
}

// An include's mirror rule: a material named off is no mirror, lower thresholds make more of them.
TEST(SceneLoader, AnIncludesMirrorRuleOverridesTheGltfThresholds) {
  Result<Scene> scene = loadSceneFile(fs::path(SPECULA_TEST_DATA_DIR) / "gltf" / "mirror-rule.json");
  ASSERT_TRUE(scene.ok()) << scene.error();
  const auto named = [&](const std::string& name) {
    return std::find_if(scene->objects.begin(), scene->objects.end(),
                        [&](const SceneObject& o) { return o.name == name; });
  };
  ASSERT_NE(named("ball/sphere"), scene->objects.end());
  EXPECT_FALSE(named("ball/sphere")->mirror.has_value()) << "\"chrome\": false";
  ASSERT_NE(named("engine/dipstick"), scene->objects.end());
  EXPECT_TRUE(named("engine/dipstick")->mirror.has_value())
      << "copper, metallic 0.8 and roughness 0.3, passes 0.75 / 0.3";
  EXPECT_TRUE(named("engine/flywheel")->mirror.has_value()) << "chrome still passes";
  EXPECT_FALSE(named("engine/block")->mirror.has_value());
  EXPECT_EQ(scene->mirrorCount(), 10u) << "the engine's six chrome parts and its four copper ones";
}

// What an included glTF file holds that is not read is named with that file, not dropped with the include.
TEST(SceneLoader, AnIncludedFilesNotesReachTheSceneWithItsName) {
  const fs::path dir = fs::path(testing::TempDir()) / "specula-SceneLoader-include-notes";
  fs::create_directories(dir);
  std::ifstream source(fs::path(SPECULA_TEST_DATA_DIR) / "gltf" / "node-tree.gltf");
  nlohmann::json gltf = nlohmann::json::parse(source);
  gltf["extensionsUsed"] = {"KHR_materials_clearcoat"};
  std::ofstream(dir / "clearcoat.gltf") << gltf.dump();
  std::ofstream(dir / "scene.json") << R"({"specula_scene": 1, "camera": {"eye": [0, 2, 6], "target": [0, 0, 0]},
      "includes": [{"name": "part", "file": "clearcoat.gltf"}]})";
  Result<Scene> scene = loadSceneFile(dir / "scene.json");
  ASSERT_TRUE(scene.ok()) << scene.error();
  ASSERT_EQ(scene->notes.size(), 1u);
  EXPECT_EQ(scene->notes[0], "clearcoat.gltf: extension KHR_materials_clearcoat is not read: what it adds is left out");
  fs::remove_all(dir);
}
