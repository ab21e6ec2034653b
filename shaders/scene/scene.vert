#version 430 core
// Scene geometry seen directly from the eye.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

uniform mat4 objectToWorld;
uniform mat3 normalToWorld;
uniform mat4 worldToClip;

out vec3 worldPosition;
out vec3 worldNormal;
out vec2 surfaceUv;

void main() {
  vec4 world = objectToWorld * vec4(inPosition, 1.0);
  worldPosition = world.xyz;
  worldNormal = normalToWorld * inNormal;
  surfaceUv = inUv;
  gl_Position = worldToClip * world;
}
