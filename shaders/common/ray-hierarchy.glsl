// The ray hierarchy of a mirror (Szabo 2013, ch. 4): mip levels of bounding spheres of its G-buffer
// positions (xyz centre, w radius) and bounding cones of its reflected eye rays (xyz unit axis, w
// half-angle in radians); w < 0 where the mirror covers none of a texel's leaves. Level sizes halve
// rounding down, as GL mip sizes do, so the last texel of an odd row or column has three children.

// The texels of the level below that texel `parent` of a level `parentSize` texels large bounds:
// from `low` to `high`, inclusive.
void rayHierarchyChildren(ivec2 parent, ivec2 parentSize, ivec2 childSize, out ivec2 low, out ivec2 high) {
  low = parent * 2;
  high = min(ivec2(parent.x == parentSize.x - 1 ? childSize.x - 1 : low.x + 1,
                   parent.y == parentSize.y - 1 ? childSize.y - 1 : low.y + 1),
             childSize - 1);
}

// Angle between two unit vectors, accurate near zero, where acos of their dot product is not.
float angleBetween(vec3 a, vec3 b) { return atan(length(cross(a, b)), dot(a, b)); }
