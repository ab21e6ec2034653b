#include "scene/GltfImporter.h"

#include "scene/AssetFiles.h"
#include "scene/gltf/GltfFile.h"
#include "scene/gltf/GltfMeshes.h"
#include "scene/gltf/GltfScene.h"

namespace specula::scene {

namespace fs = std::filesystem;

Result<Mesh> importGltf(const fs::path& file, const GltfMeshSelector& which, std::string meshName) {
  Result<std::string> bytes = readBoundedFile(file, kMaxAssetFileBytes);
  if (!bytes) return Error{bytes.error()};
  gltf::DecodedImages images;  // a mesh for a JSON scene draws in the scene's materials: its images are not read
  Result<tinygltf::Model> model = gltf::loadModel(bytes.value(), file.parent_path(), images);
  if (!model) return Error{file.string() + ": " + model.error()};
  Result<std::size_t> chosen = gltf::selectMesh(model.value(), which);
  if (!chosen) return Error{file.string() + ": " + chosen.error()};
  Result<Mesh> mesh = gltf::readMesh(model.value(), chosen.value(), std::move(meshName));
  if (!mesh) return Error{file.string() + ": " + mesh.error()};
  return mesh;
}

Result<ImportedGltfScene> importGltfScene(const fs::path& file, const GltfSceneChoice& choice) {
  Result<std::string> bytes = readBoundedFile(file, kMaxAssetFileBytes);
  if (!bytes) return Error{bytes.error()};
  gltf::DecodedImages images{true, {}, 0, {}};
  Result<tinygltf::Model> model = gltf::loadModel(bytes.value(), file.parent_path(), images);
  if (!model) return Error{file.string() + ": " + model.error()};
  Result<ImportedGltfScene> scene = gltf::sceneFromModel(model.value(), images, choice, file.stem().string());
  if (!scene) return Error{file.string() + ": " + scene.error()};
  return scene;
}

Result<ImportedGltfScene> importGltfScene(const fs::path& file) {
  static const GltfSceneChoice kDefault;  // not a temporary per call: GCC 12 misjudges its map's destruction
  return importGltfScene(file, kDefault);
}

}  // namespace specula::scene
