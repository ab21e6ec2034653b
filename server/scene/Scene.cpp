#include "scene/Scene.h"

namespace specula::scene {

std::size_t Scene::vertexCount() const {
  std::size_t n = 0;
  for (const SceneObject& o : objects) n += o.mesh < meshes.size() ? meshes[o.mesh].vertices.size() : 0;
  return n;
}

std::size_t Scene::triangleCount() const {
  std::size_t n = 0;
  for (const SceneObject& o : objects) n += o.mesh < meshes.size() ? meshes[o.mesh].triangleCount() : 0;
  return n;
}

std::size_t Scene::mirrorCount() const {
  std::size_t n = 0;
  for (const SceneObject& o : objects) n += o.mirror.has_value();
  return n;
}

}  // namespace specula::scene
