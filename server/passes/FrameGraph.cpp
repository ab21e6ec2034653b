#include "passes/FrameGraph.h"

#include <algorithm>

namespace specula::passes {

namespace {
bool contains(const std::vector<FrameResource>& resources, FrameResource resource) {
  return std::find(resources.begin(), resources.end(), resource) != resources.end();
}

// What the search starts from, by strategy (the refined explosion map climbs from the pyramid where
// the map's point is off the part).
std::vector<FrameResource> searchInputs(const FrameNeeds& needs) {
  std::vector<FrameResource> reads{FrameResource::MirrorGBuffer};
  if (!needs.strategyNeeded) return reads;
  switch (needs.search) {
    case SearchStrategy::Crosshair: reads.push_back(FrameResource::GBufferPyramid); break;
    case SearchStrategy::Hierarchy: reads.push_back(FrameResource::RayHierarchy); break;
    case SearchStrategy::ExplosionMap:
      reads.push_back(FrameResource::ExplosionMaps);
      if (needs.explosionRefine) reads.push_back(FrameResource::GBufferPyramid);
      break;
  }
  return reads;
}
}  // namespace

const char* passName(PassId pass) {
  switch (pass) {
    case PassId::Scene: return "scene";
    case PassId::MirrorGBuffer: return "mirror-gbuffer";
    case PassId::GBufferPyramid: return "gbuffer-pyramid";
    case PassId::RayHierarchy: return "ray-hierarchy";
    case PassId::ExplosionMap: return "explosion-map";
    case PassId::Search: return "search";
    case PassId::Tessellation: return "tessellation";
    case PassId::VirtualObjects: return "virtual-objects";
    case PassId::EnvironmentMap: return "environment-map";
  }
  return "?";
}

const char* resourceName(FrameResource resource) {
  switch (resource) {
    case FrameResource::FrameImage: return "the frame image";
    case FrameResource::MirrorGBuffer: return "the mirror G-buffer";
    case FrameResource::GBufferPyramid: return "the G-buffer pyramid";
    case FrameResource::RayHierarchy: return "the ray hierarchy";
    case FrameResource::ExplosionMaps: return "the explosion maps";
    case FrameResource::ReflectedVertices: return "the reflected vertices";
    case FrameResource::TessellatedTriangles: return "the tessellated triangles";
    case FrameResource::EnvironmentCubes: return "the environment cubes";
  }
  return "?";
}

PassDeclaration declaration(PassId pass, const FrameNeeds& needs) {
  using R = FrameResource;
  switch (pass) {
    case PassId::Scene: return {{}, {R::FrameImage}};
    case PassId::MirrorGBuffer: return {{}, {R::MirrorGBuffer}};
    case PassId::GBufferPyramid: return {{R::MirrorGBuffer}, {R::GBufferPyramid}};
    case PassId::RayHierarchy: return {{R::MirrorGBuffer}, {R::RayHierarchy}};
    case PassId::ExplosionMap: return {{}, {R::ExplosionMaps}};
    case PassId::Search: return {searchInputs(needs), {R::ReflectedVertices}};
    case PassId::Tessellation: {
      std::vector<R> reads = searchInputs(needs);  // midpoints are searched like vertices
      reads.push_back(R::ReflectedVertices);       // round 0's corners
      return {reads, {R::TessellatedTriangles}};
    }
    case PassId::VirtualObjects: {
      // Ray-cast parts need only the G-buffer; searched ones draw meshes at their search slots, and
      // the tessellation's triangles when it ran.
      std::vector<R> reads{R::FrameImage, R::MirrorGBuffer};
      if (needs.searched) reads.push_back(R::ReflectedVertices);
      if (needs.tessellated) reads.push_back(R::TessellatedTriangles);
      return {reads, {R::FrameImage}};
    }
    case PassId::EnvironmentMap: return {{R::FrameImage, R::MirrorGBuffer}, {R::EnvironmentCubes, R::FrameImage}};
  }
  return {};
}

std::optional<std::string> planProblem(const std::vector<PassId>& passes, const FrameNeeds& needs) {
  std::vector<FrameResource> written;
  for (PassId pass : passes) {
    const PassDeclaration declared = declaration(pass, needs);
    for (FrameResource read : declared.reads)
      if (!contains(written, read))
        return std::string("frame plan: pass '") + passName(pass) + "' reads " + resourceName(read) +
               ", which no pass before it writes";
    written.insert(written.end(), declared.writes.begin(), declared.writes.end());
  }
  return std::nullopt;
}

std::vector<PassId> cullUnread(const std::vector<PassId>& passes, const FrameNeeds& needs) {
  // Backwards from the frame image: a pass stays when it writes the image or something a kept pass
  // after it reads.
  std::vector<FrameResource> needed{FrameResource::FrameImage};
  std::vector<PassId> kept;
  for (auto pass = passes.rbegin(); pass != passes.rend(); ++pass) {
    const PassDeclaration declared = declaration(*pass, needs);
    const bool used = std::any_of(declared.writes.begin(), declared.writes.end(),
                                  [&](FrameResource r) { return contains(needed, r); });
    if (!used) continue;
    kept.insert(kept.begin(), *pass);
    needed.insert(needed.end(), declared.reads.begin(), declared.reads.end());
  }
  return kept;
}

}  // namespace specula::passes
