#version 430 core
// A mirror's (closed) surface from the eye through a widened frustum: world positions and normals.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

uniform mat4 objectToWorld;
uniform mat3 normalToWorld;
uniform mat4 worldToClip;  // the eye's projection widened by the G-buffer margin

out vec3 worldPosition;
out vec3 worldNormal;

void main() {
  vec4 world = objectToWorld * vec4(inPosition, 1.0);
  worldPosition = world.xyz;
  worldNormal = normalToWorld * inNormal;
  gl_Position = worldToClip * world;
}
