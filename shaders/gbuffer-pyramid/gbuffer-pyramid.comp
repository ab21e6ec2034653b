#version 430 core
// The pyramid of an RGBA32F G-buffer.
#define GBUFFER_FORMAT rgba32f
#include "gbuffer-pyramid/pyramid-level.glsl"
