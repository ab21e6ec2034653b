// The frame graph without GL: every resource a pass reads is written before it, and a pass whose
// output nothing reads does not run.
#include <gtest/gtest.h>

#include "passes/FrameGraph.h"

namespace specula::passes {
namespace {

FrameNeeds searchedAndTessellated(SearchStrategy search = SearchStrategy::Crosshair) {
  FrameNeeds needs;
  needs.search = search;
  needs.searched = needs.tessellated = true;
  return needs;
}

TEST(FrameGraph, APlanThatReadsWhatNothingWroteIsRefusedNamingThePassAndTheResource) {
  const FrameNeeds needs = searchedAndTessellated();
  const auto problem =
      planProblem({PassId::Scene, PassId::MirrorGBuffer, PassId::Search, PassId::VirtualObjects}, needs);
  ASSERT_TRUE(problem);
  EXPECT_EQ(*problem, "frame plan: pass 'search' reads the G-buffer pyramid, which no pass before it writes");
  const auto late = planProblem({PassId::Scene, PassId::MirrorGBuffer, PassId::GBufferPyramid, PassId::Search,
                                 PassId::VirtualObjects, PassId::Tessellation},
                                needs);
  ASSERT_TRUE(late) << "written after it is read";
  EXPECT_NE(late->find("'virtual-objects' reads the tessellated triangles"), std::string::npos) << *late;
  EXPECT_FALSE(planProblem({PassId::Scene, PassId::MirrorGBuffer, PassId::GBufferPyramid, PassId::Search,
                            PassId::Tessellation, PassId::VirtualObjects},
                           needs));
}

TEST(FrameGraph, EachSearchReadsWhatItsStrategyStartsFrom) {
  FrameNeeds hierarchy = searchedAndTessellated(SearchStrategy::Hierarchy);
  EXPECT_TRUE(planProblem({PassId::Scene, PassId::MirrorGBuffer, PassId::GBufferPyramid, PassId::Search}, hierarchy));
  EXPECT_FALSE(planProblem({PassId::Scene, PassId::MirrorGBuffer, PassId::RayHierarchy, PassId::Search}, hierarchy));
  FrameNeeds maps = searchedAndTessellated(SearchStrategy::ExplosionMap);
  EXPECT_FALSE(planProblem({PassId::Scene, PassId::MirrorGBuffer, PassId::ExplosionMap, PassId::Search}, maps));
  maps.explosionRefine = true;  // the refinement climbs from the pyramid where a map's point is off the part
  EXPECT_TRUE(planProblem({PassId::Scene, PassId::MirrorGBuffer, PassId::ExplosionMap, PassId::Search}, maps));
  FrameNeeds extrusions = searchedAndTessellated();
  extrusions.strategyNeeded = false;  // solved in 2-D: nothing to start from
  EXPECT_FALSE(planProblem({PassId::Scene, PassId::MirrorGBuffer, PassId::Search}, extrusions));
}

TEST(FrameGraph, PassesWhoseOutputNothingReadsAreCulled) {
  FrameNeeds rayCast;  // every part ray-cast: the virtual-objects pass reads no search result
  const std::vector<PassId> everything{PassId::Scene,        PassId::MirrorGBuffer, PassId::GBufferPyramid,
                                       PassId::RayHierarchy, PassId::ExplosionMap,  PassId::Search,
                                       PassId::Tessellation, PassId::VirtualObjects};
  EXPECT_EQ(cullUnread(everything, rayCast),
            (std::vector<PassId>{PassId::Scene, PassId::MirrorGBuffer, PassId::VirtualObjects}));
  const FrameNeeds searched = searchedAndTessellated();
  EXPECT_EQ(cullUnread(everything, searched),
            (std::vector<PassId>{PassId::Scene, PassId::MirrorGBuffer, PassId::GBufferPyramid, PassId::Search,
                                 PassId::Tessellation, PassId::VirtualObjects}))
      << "the crosshair search reads neither the hierarchy nor the maps";
  FrameNeeds untessellated = searched;
  untessellated.tessellated = false;
  const std::vector<PassId> kept = cullUnread(everything, untessellated);
  EXPECT_EQ(std::count(kept.begin(), kept.end(), PassId::Tessellation), 0);
  EXPECT_EQ(std::count(kept.begin(), kept.end(), PassId::Search), 1);
  EXPECT_EQ(cullUnread({PassId::Scene, PassId::MirrorGBuffer}, rayCast), std::vector<PassId>{PassId::Scene})
      << "a G-buffer nothing reads";
}

TEST(FrameGraph, EveryPassHasItsShaderFoldersName) {
  for (PassId pass : kPassIds) EXPECT_STRNE(passName(pass), "?");
  EXPECT_STREQ(passName(PassId::VirtualObjects), "virtual-objects");
  EXPECT_STREQ(passName(PassId::GBufferPyramid), "gbuffer-pyramid");
}

}  // namespace
}  // namespace specula::passes
