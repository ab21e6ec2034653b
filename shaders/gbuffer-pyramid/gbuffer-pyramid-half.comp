#version 430 core
// The pyramid of an RGBA16F G-buffer (image formats must match the texture's).
#define GBUFFER_FORMAT rgba16f
#include "gbuffer-pyramid/pyramid-level.glsl"
