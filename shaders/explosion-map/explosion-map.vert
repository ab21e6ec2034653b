#version 430 core
// One vertex of a mirror part for the explosion map: its world position, the normal the map uses
// (common/explosion-map.glsl) and where its reflected ray meets this map's sphere.
#include "common/explosion-map.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

uniform mat4 objectToWorld;
uniform mat3 normalToWorld;
uniform vec3 eyePosition;
uniform int farMap;  // 0: the near map (sphere radius explosionRadii.x), 1: the far one (.y)

out vec3 mapWorldPosition;
out vec3 mapWorldNormal;
out vec2 mapCoords;
out float frontFacing;  // 1 when the vertex faces the eye

void main() {
  vec3 world = (objectToWorld * vec4(inPosition, 1.0)).xyz;
  vec3 normal = normalize(normalToWorld * inNormal);
  frontFacing = dot(normal, eyePosition - world) > 0.0 ? 1.0 : 0.0;
  mapWorldPosition = world;
  mapWorldNormal = explosionNormal(world, normal, eyePosition);
  mapCoords = explosionVertexCoords(world, mapWorldNormal, eyePosition, farMap != 0 ? explosionRadii.y : explosionRadii.x);
  gl_Position = vec4(0.0);  // placed by the geometry shader
}
