#version 430 core

in vec3 worldPosition;
in vec3 worldNormal;

layout(location = 0) out vec4 outPosition;  // w = 1 marks a mirror texel
layout(location = 1) out vec4 outNormal;

void main() {
  outPosition = vec4(worldPosition, 1.0);
  outNormal = vec4(normalize(worldNormal), 0.0);
}
