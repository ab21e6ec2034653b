#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace specula::passes {

enum class ReflectionMethod {
  None,    // mirrors drawn with their own colour only
  Search,  // virtual objects from the screen-space reflection-point search (Estalella et al. 2006)
  // The baseline most engines use instead: a cube map rendered from each mirror's centre, looked up
  // with the reflected eye ray. Exact only for surroundings infinitely far away (no parallax).
  EnvironmentMap,
};

// How the search finds the G-buffer texel nearest each vertex's reflection point, which it then
// refines below the texel.
enum class SearchStrategy {
  // Estalella et al. 2006: hill-climb N·B in 3×3 windows from last frame's texel (coherence); cold
  // starts scan a coarse level of the averaged G-buffer pyramid and climb down.
  Crosshair,
  // Szabo 2013, ch. 4: top-down through a pyramid of bounding spheres of the mirror's positions and
  // cones of its reflected eye rays, into the cones that hold the vertex. No coherence.
  Hierarchy,
  // Ofek & Rappoport 1998, §4: no search. Per part and frame, near and far explosion maps (the
  // part's reflected-ray directions through a sphere about it); a vertex is mirrored across the
  // planes the maps give in the direction from the part's centre to it, hidden ones across the
  // surface in front of them. Optionally refined by the crosshair climb from the map's point.
  ExplosionMap,
};

inline constexpr SearchStrategy kSearchStrategies[] = {SearchStrategy::Crosshair, SearchStrategy::Hierarchy,
                                                       SearchStrategy::ExplosionMap};

// "crosshair", "hierarchy" or "explosion-map": how reports and the command line name a strategy.
const char* searchStrategyName(SearchStrategy strategy);
std::optional<SearchStrategy> parseSearchStrategy(std::string_view name);

// What a virtual triangle's fragments show.
enum class VirtualPixels {
  // Each fragment casts its pixel's reflected ray against the object triangle and shows the exact
  // hit (or nothing): the triangle's placement decides only which pixels it is tried at.
  ExactHit,
  // The papers' rendering: the triangle is shaded where it lies, kept to the mirror's own pixels (the
  // stencil is Ofek & Rappoport's second z-buffer), so placement errors show as displaced reflections.
  AsPlaced,
};

// Storage of the mirror G-buffer's world positions and normals.
enum class GBufferPrecision {
  Float32,  // RGBA32F
  // RGBA16F: half the memory and bandwidth; positions keep 11 bits of mantissa, so frames whose
  // mirrors lie far from the origin use RGBA32F instead (passes::halfFloatsResolve).
  Float16,
};

// Adaptive tessellation of reflected geometry (Szabo 2013, ch. 4), so virtual edges curve.
enum class TessellationMode {
  None,       // virtual triangles straight between their corners' reflections
  Paper,      // Szabo's loop: a triangle whose worst edge exceeds the threshold splits 1→4
  CrackFree,  // each edge decided alone and split triangles follow conforming patterns: no T-junctions
};

enum class TessellationMetric {
  Angle,   // Szabo's edge error 1 − (N_mid·b + 1)/2, from 0 to 1
  Pixels,  // where the rasterizer puts the edge midpoint against where its true reflection projects
};

// Which mirror parts the frame plan ray-casts instead of searching (passes/FramePlan).
enum class RayCastRule {
  WhenCheaper,  // the parts for which the planner's cost model predicts casting cheaper than searching
  Never,        // search every part (the virtual-objects method alone)
  Always,       // ray-cast every part
};

// What the frame plan leaves out (passes/FramePlan).
enum class PlanScope {
  Needed,      // mirrors out of view, and reflected objects a mirror part cannot show (behind it, in its shadow)
  Everything,  // nothing: every mirror part searches every reflected object (the planner off, for comparison)
};

struct TessellationSettings {
  TessellationMode mode = TessellationMode::CrackFree;
  TessellationMetric metric = TessellationMetric::Pixels;
  float threshold = 1.0f;  // an edge splits when its error is at least this (0: always; Angle 1: never)
  int maxLevel = 4;        // splits per original triangle at most: at most 4^maxLevel triangles each

  bool operator==(const TessellationSettings&) const = default;
};

// "crack-free pixels >= 1 level 4", or "none": how reports name a setting.
std::string describeTessellation(const TessellationSettings& settings);

// The ranges reflectionSettingsProblem() accepts (and the command-line options name).
inline constexpr float kMinGBufferScale = 0.125f, kMaxGBufferScale = 4.0f;
inline constexpr int kMinEnvironmentMapSize = 8, kMaxEnvironmentMapSize = 2048;
inline constexpr float kMaxErrorBudgetPixels = 16.0f;
inline constexpr int kMinExplosionMapSize = 16, kMaxExplosionMapSize = 4096;
inline constexpr int kMaxTessellationLevel = 8;  // 4^8 = 65 536 triangles from one: the lists' cap stops it anyway

struct ReflectionSettings {
  ReflectionMethod method = ReflectionMethod::Search;
  // Extra G-buffer border on each side, as a share of the frame size, so reflection points of a
  // mirror just off-screen still have texels.
  float gbufferMargin = 0.1f;
  // G-buffer texels per frame pixel along each axis (1: one texel per pixel), in [kMin, kMaxGBufferScale].
  float gbufferScale = 1.0f;
  GBufferPrecision gbufferPrecision = GBufferPrecision::Float32;
  int environmentMapSize = 256;  // cube face side in texels (EnvironmentMap), in [kMin, kMaxEnvironmentMapSize]
  SearchStrategy search = SearchStrategy::Crosshair;
  // ExplosionMap: each map's side in texels, in [kMin, kMaxExplosionMapSize] (the paper: 200 for a
  // mirror of several hundred triangles), and whether the crosshair search refines what it gives.
  int explosionMapSize = 256;
  bool explosionRefine = false;
  // ExplosionMap: place a visible vertex as the paper does, mirrored across the maps' planes, instead
  // of on the eye's ray through the reflection point they give.
  bool explosionMirrorPlacement = false;
  VirtualPixels virtualPixels = VirtualPixels::ExactHit;
  // Mirrors declared as linear extrusions (a cylinder: scene::MirrorInfo::extrusion) have their
  // reflection points solved by Ofek & Rappoport's 2-D reduction, exactly and with no search; off
  // searches their meshes with `search` like any mirror (the extrusion then only measures them).
  bool solveExtrusions = true;
  // Start each vertex's search at last frame's texel; off forces cold starts (benchmarks, jumps).
  bool coherence = true;
  int maxWalkSteps = 64;  // bound on 3×3 windows per climb
  PlanScope plan = PlanScope::Needed;
  // Which parts have each pixel's reflected ray cast against their reflected objects (exact) instead
  // of searching the objects' every vertex.
  RayCastRule rayCast = RayCastRule::WhenCheaper;
  // A ray-cast part of several objects casts each only on the 8×8 tiles whose rays may reach its
  // bounding sphere; off casts every object over the whole part (the reference the classification is tested against).
  bool castTiles = true;
  // A searched part's pixels no virtual object landed on (coverage gaps at silhouettes and rims)
  // have their reflected rays cast against the part's reflected objects; off shows the background.
  bool rayCastUncovered = true;
  // Pixels the planner's approximations may move a reflection by (in [0, kMaxErrorBudgetPixels]):
  // a reflected object whose image in a convex part is smaller than this is left out, and a mirror
  // smaller than this on screen shows its own colour. 0: only exact decisions.
  float errorBudgetPixels = 0.5f;
  TessellationSettings tessellation;

  bool operator==(const ReflectionSettings&) const = default;
};

// What is out of range in `settings`, naming the setting and its range; nullopt when all is well.
std::optional<std::string> reflectionSettingsProblem(const ReflectionSettings& settings);

}  // namespace specula::passes
