// The records of a mesh's hierarchy: std430 twins of math::TriangleBvh::Node and ::Triangle.

struct BvhNode {
  vec3 low;
  uint first;  // inner node: first of its two children; leaf: its first triangle
  vec3 high;
  uint count;  // triangles of a leaf; 0 for an inner node
};
struct BvhTriangle {
  vec3 a;
  uint index;  // the triangle in the mesh
  vec3 b;
  float unused0;
  vec3 c;
  float unused1;
};
