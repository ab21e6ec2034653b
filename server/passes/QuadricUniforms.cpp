#include "passes/QuadricUniforms.h"

#include "math/Transform.h"

namespace specula::passes {

bool hasExactQuadric(const scene::MirrorInfo& mirror) { return mirror.analytic.has_value() && mirror.closed; }

void setMirrorQuadric(const gl::ShaderProgram& program, const scene::MirrorInfo& mirror, const glm::mat4& objectToWorld) {
  const bool analytic = hasExactQuadric(mirror);
  program.set("analytic", analytic ? 1 : 0);
  if (!analytic) return;
  program.set("quadricWorldToObject", glm::inverse(objectToWorld));
  program.set("quadricObjectToWorld", objectToWorld);
  program.set("quadricNormalToWorld", math::normalMatrix(objectToWorld));
  program.set("quadricCenter", mirror.analytic->center);
  program.set("quadricRadii", mirror.analytic->radii);
}

}  // namespace specula::passes
