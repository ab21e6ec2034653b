#version 430 core
// Resets the mirror's depth before its virtual objects (colour masked), then adds the reflected
// background where no virtual object landed (depth still on the far plane).
uniform vec3 reflectedBackground;  // background × reflectivity, linear RGB
layout(location = 0) out vec4 outColor;
void main() { outColor = vec4(reflectedBackground, 1.0); }
