#pragma once
// The frame graph's vocabulary: the passes a frame can run and the resources they read and write,
// as plain data. The planner lists passes; planProblem() checks that every resource a pass reads was
// written before it, and cullUnread() drops passes whose writes nothing reads.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "passes/ReflectionSettings.h"  // SearchStrategy

namespace specula::passes {

// Each named like its shaders/ folder (passName()).
enum class PassId {
  Scene,
  MirrorGBuffer,
  GBufferPyramid,
  RayHierarchy,
  ExplosionMap,
  Search,
  Tessellation,
  VirtualObjects,
  EnvironmentMap
};
inline constexpr std::array kPassIds{PassId::Scene,        PassId::MirrorGBuffer,  PassId::GBufferPyramid,
                                     PassId::RayHierarchy, PassId::ExplosionMap,   PassId::Search,
                                     PassId::Tessellation, PassId::VirtualObjects, PassId::EnvironmentMap};
const char* passName(PassId pass);

// What passes hand each other within a frame.
enum class FrameResource {
  FrameImage,            // the target's colour, depth and mirror stencil: the frame itself
  MirrorGBuffer,         // each visible mirror part's positions, normals and covered texels
  GBufferPyramid,        // its averaged levels: where cold searches start
  RayHierarchy,          // bounding spheres and cones of its reflected rays
  ExplosionMaps,         // each part's near and far maps of reflected-ray directions
  ReflectedVertices,     // every reflected vertex's reflection point this frame
  TessellatedTriangles,  // the finished triangles and the indirect draws of every run
  EnvironmentCubes,      // each environment-mapped mirror's cube
};
const char* resourceName(FrameResource resource);

struct PassDeclaration {
  std::vector<FrameResource> reads, writes;
};

// What a frame's mirrors need, which decides what some passes read.
struct FrameNeeds {
  SearchStrategy search = SearchStrategy::Crosshair;
  bool explosionRefine = false;
  bool strategyNeeded = true;  // false when every searched part is a solved extrusion: no pyramid, hierarchy or maps
  bool searched = false;       // some part is drawn as virtual objects
  bool tessellated = false;    // their triangles come from the tessellation
};

// What `pass` reads and writes in a frame with these needs.
PassDeclaration declaration(PassId pass, const FrameNeeds& needs);

// Names the first pass that reads a resource no pass before it wrote, and the resource; nullopt
// when every read is written first.
std::optional<std::string> planProblem(const std::vector<PassId>& passes, const FrameNeeds& needs);

// The passes, in order, whose writes a later pass reads or that write the frame image.
std::vector<PassId> cullUnread(const std::vector<PassId>& passes, const FrameNeeds& needs);

}  // namespace specula::passes
