#include "passes/QuadricUniforms.h"

#include "math/Transform.h"

namespace specula::passes {

void setMirrorQuadric(const gl::ShaderProgram& program, const scene::MirrorInfo& mirror,
                      const glm::mat4& objectToWorld) {
  const bool analytic = mirror.exactQuadric();
  program.set("analytic", analytic ? 1 : 0);
  if (!analytic) return;
  program.set("quadricWorldToObject", glm::inverse(objectToWorld));
  program.set("quadricObjectToWorld", objectToWorld);
  program.set("quadricNormalToWorld", math::normalMatrix(objectToWorld));
  program.set("quadricCenter", mirror.analytic->center);
  program.set("quadricRadii", mirror.analytic->radii);
}

void setMirrorExtrusion(const gl::ShaderProgram& program, const scene::MirrorInfo& mirror,
                        const glm::mat4& objectToWorld, bool solve) {
  const std::optional<math::Extrusion> world =
      solve && mirror.extrusion ? mirror.extrusion->transformed(glm::dmat4(objectToWorld)) : std::nullopt;
  program.set("extrusion", world ? 1 : 0);
  if (!world) return;
  program.set("extrusionAxisPoint", glm::vec3(world->axisPoint));
  program.set("extrusionU", glm::vec3(world->u));
  program.set("extrusionV", glm::vec3(world->v));
  program.set("extrusionDirection", glm::vec3(world->direction));
  program.set("extrusionRadii", glm::vec2(world->radii));
}

}  // namespace specula::passes
