// Surface colour and lighting shared by every pass that shades scene geometry (direct and reflected),
// so a reflected object is lit exactly as the object itself: at its own world position and normal.
// Colours are linear RGB; the sRGB framebuffer encodes them on write.

const int kMaxLights = 8;  // scene::kMaxLights

uniform vec3 materialBaseColor;
uniform int materialUnlit;           // 1: emissive, the colour written is the colour stored
uniform int materialHasChecker;
uniform vec3 materialCheckerOddColor;
uniform float materialCheckerCellsPerUnit;
uniform sampler2D materialTexture;  // passes::GpuTextures::kMaterialTextureUnit; white when the material has none
uniform int materialHasTexture;     // 0: no texture fetch at all (an explicit-gradient fetch is dear on a CPU rasterizer)

uniform vec3 sceneAmbient;
uniform int lightCount;
uniform vec4 lightVector[kMaxLights];  // w = 0: direction towards the light; w = 1: position
uniform vec3 lightColor[kMaxLights];   // colour × intensity

// The texture is filtered over the pixel's footprint in uv (uvDx, uvDy: uv across one pixel).
vec3 surfaceColor(vec2 uv, vec2 uvDx, vec2 uvDy) {
  vec3 color = materialBaseColor;
  if (materialHasChecker != 0) {
    ivec2 cell = ivec2(floor(uv * materialCheckerCellsPerUnit));
    if (((cell.x + cell.y) & 1) != 0) color = materialCheckerOddColor;
  }
  if (materialHasTexture != 0) color *= textureGrad(materialTexture, uv, uvDx, uvDy).rgb;
  return color;
}

// Lambertian shading of a point seen from `viewer`; faces turned away from the viewer are lit
// on their visible side, so open meshes (floors, leaves) look right from both sides.
vec3 shadeSurface(vec3 position, vec3 normal, vec2 uv, vec2 uvDx, vec2 uvDy, vec3 viewer) {
  vec3 albedo = surfaceColor(uv, uvDx, uvDy);
  if (materialUnlit != 0) return albedo;
  vec3 n = normalize(normal);
  if (dot(n, viewer - position) < 0.0) n = -n;
  vec3 color = sceneAmbient * albedo;
  for (int i = 0; i < lightCount; ++i) {
    vec3 toLight = lightVector[i].w == 0.0 ? lightVector[i].xyz : normalize(lightVector[i].xyz - position);
    color += albedo * lightColor[i] * max(dot(n, toLight), 0.0);
  }
  return color;
}

// A pixel's footprint on a surface hit by a traced ray (ray-cast pixels; reference::pixelFootprint
// restates it): the ray cone's width where it arrives, `pathLength` along a ray whose eye ray is
// `eyeDepthPerLength` deep per unit length, stretched by the hit's obliquity `cosine`, in metres.
const float kMinFootprintCosine = 0.01;
float pixelFootprint(float pathLength, float eyeDepthPerLength, float pixelAngle, float cosine) {
  return pathLength * eyeDepthPerLength * pixelAngle / max(abs(cosine), kMinFootprintCosine);
}

// How fast uv changes per metre across a triangle (world corners p, their uv): the root of the
// ratio of its areas in uv and in space; 0 for a degenerate triangle.
float uvPerMetre(vec3 p0, vec3 p1, vec3 p2, vec2 uv0, vec2 uv1, vec2 uv2) {
  float area = length(cross(p1 - p0, p2 - p0));
  vec2 a = uv1 - uv0, b = uv2 - uv0;
  return area > 0.0 ? sqrt(abs(a.x * b.y - a.y * b.x) / area) : 0.0;
}

// shadeSurface with an isotropic footprint of `uvFootprint` uv units.
vec3 shadeSurfaceOver(vec3 position, vec3 normal, vec2 uv, float uvFootprint, vec3 viewer) {
  return shadeSurface(position, normal, uv, vec2(uvFootprint, 0.0), vec2(0.0, uvFootprint), viewer);
}
