#version 430 core
// Resets a mirror's depth before its virtual objects are drawn (colour is masked).
layout(location = 0) out vec4 outColor;
void main() { outColor = vec4(0.0); }
