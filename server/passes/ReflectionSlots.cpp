#include "passes/ReflectionSlots.h"

namespace specula::passes {

ReflectionSlots ReflectionSlots::forScene(const scene::Scene& scene) {
  ReflectionSlots slots;
  for (std::size_t m = 0; m < scene.objects.size(); ++m) {
    if (!scene.objects[m].mirror || scene.materials[scene.objects[m].material].reflectivity <= 0.0f) continue;
    MirrorSlots mirror{m, static_cast<int>(slots.mirrors.size()), {}};
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
      if (o == m || !scene.objects[o].reflected) continue;
      mirror.reflected.push_back({o, slots.slotCount});
      slots.slotCount += static_cast<std::uint32_t>(scene.meshes[scene.objects[o].mesh].vertices.size());
    }
    slots.mirrors.push_back(std::move(mirror));
  }
  return slots;
}

}  // namespace specula::passes
