// Surface colour and lighting shared by every pass that shades scene geometry (direct and reflected),
// so a reflected object is lit exactly as the object itself: at its own world position and normal.
// Colours are linear RGB; the sRGB framebuffer encodes them on write.

const int kMaxLights = 8;  // scene::kMaxLights

uniform vec3 materialBaseColor;
uniform int materialUnlit;           // 1: emissive, the colour written is the colour stored
uniform int materialHasChecker;
uniform vec3 materialCheckerOddColor;
uniform float materialCheckerCellsPerUnit;

uniform vec3 sceneAmbient;
uniform int lightCount;
uniform vec4 lightVector[kMaxLights];  // w = 0: direction towards the light; w = 1: position
uniform vec3 lightColor[kMaxLights];   // colour × intensity

vec3 surfaceColor(vec2 uv) {
  if (materialHasChecker == 0) return materialBaseColor;
  ivec2 cell = ivec2(floor(uv * materialCheckerCellsPerUnit));
  return ((cell.x + cell.y) & 1) == 0 ? materialBaseColor : materialCheckerOddColor;
}

// Lambertian shading of a point seen from `viewer`; faces turned away from the viewer are lit
// on their visible side, so open meshes (floors, leaves) look right from both sides.
vec3 shadeSurface(vec3 position, vec3 normal, vec2 uv, vec3 viewer) {
  vec3 albedo = surfaceColor(uv);
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
