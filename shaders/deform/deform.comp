#version 430 core
// A deforming mesh at this frame's pose, written into the vertex buffer every pass reads: each vertex's
// rest position and normal plus its weighted morph target displacements, then skinned by the blend of
// its joints' matrices (the normal by the blend's inverse transpose) and renormalised. The CPU poses the
// reference with scene::deformedVertices, its own code.
layout(local_size_x = 64) in;

struct Influences {
  uvec4 joints;
  vec4 weights;
};

layout(std430, binding = 0) readonly buffer RestVertices {
  float restVertex[];  // scene::Vertex: position xyz, normal xyz, uv — 8 floats
};
layout(std430, binding = 1) readonly buffer Displacements {
  vec4 displacement[];  // target k, vertex v: position at 2 (k·vertexCount + v), normal one after
};
layout(std430, binding = 2) readonly buffer Weights {
  float weight[];  // one per target
};
layout(std430, binding = 3) writeonly buffer MeshVertices {
  float meshVertex[];
};
layout(std430, binding = 4) readonly buffer VertexInfluences {
  Influences influences[];  // set s, vertex v: s·vertexCount + v
};
layout(std430, binding = 5) readonly buffer JointMatrices {
  mat4 joint[];  // to the mesh's space, one per joint of the skin
};

uniform uint vertexCount;
uniform uint targetCount;
uniform uint influenceSets;  // 0: not skinned

void main() {
  uint v = gl_GlobalInvocationID.x;
  if (v >= vertexCount) return;
  uint at = 8u * v;
  vec3 restNormal = vec3(restVertex[at + 3u], restVertex[at + 4u], restVertex[at + 5u]);
  vec3 position = vec3(restVertex[at], restVertex[at + 1u], restVertex[at + 2u]);
  vec3 normal = restNormal;
  for (uint k = 0u; k < targetCount; ++k) {
    uint d = 2u * (k * vertexCount + v);
    position += weight[k] * displacement[d].xyz;
    normal += weight[k] * displacement[d + 1u].xyz;
  }
  if (influenceSets > 0u) {
    mat4 blend = mat4(0.0);
    for (uint s = 0u; s < influenceSets; ++s) {
      Influences set = influences[s * vertexCount + v];
      for (int i = 0; i < 4; ++i)
        if (set.weights[i] != 0.0) blend += set.weights[i] * joint[set.joints[i]];
    }
    position = (blend * vec4(position, 1.0)).xyz;
    normal = transpose(inverse(mat3(blend))) * normal;
  }
  float length = length(normal);
  normal = length > 0.0 ? normal / length : restNormal;  // weights that cancel the normal keep the rest one
  meshVertex[at] = position.x;
  meshVertex[at + 1u] = position.y;
  meshVertex[at + 2u] = position.z;
  meshVertex[at + 3u] = normal.x;
  meshVertex[at + 4u] = normal.y;
  meshVertex[at + 5u] = normal.z;
  meshVertex[at + 6u] = restVertex[at + 6u];
  meshVertex[at + 7u] = restVertex[at + 7u];
}
