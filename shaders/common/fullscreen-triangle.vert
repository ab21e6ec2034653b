#version 430 core
// A full-screen triangle on the far plane: with the stencil test, one mirror's pixels; without, every pixel.
void main() {
  vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(corner * 2.0 - 1.0, 1.0, 1.0);
}
