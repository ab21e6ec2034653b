#include "passes/QuadricUniforms.h"

#include "math/Transform.h"

namespace specula::passes {

void setMirrorQuadric(const gl::ShaderProgram& program, const scene::MirrorInfo& mirror, const glm::mat4& objectToWorld) {
  const bool analytic = mirror.exactQuadric();
  program.set("analytic", analytic ? 1 : 0);
  if (!analytic) return;
  program.set("quadricWorldToObject", glm::inverse(objectToWorld));
  program.set("quadricObjectToWorld", objectToWorld);
  program.set("quadricNormalToWorld", math::normalMatrix(objectToWorld));
  program.set("quadricCenter", mirror.analytic->center);
  program.set("quadricRadii", mirror.analytic->radii);
}

}  // namespace specula::passes
