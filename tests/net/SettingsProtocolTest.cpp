// Settings over the protocol: what a client names is what runs.
#include <gtest/gtest.h>

#include "session/SettingsProtocol.h"

namespace specula::session {
namespace {

TEST(SettingsProtocol, ANamedSearchRunsInsteadOfTheCostModelsRayCast) {
  SessionSettings settings;
  ASSERT_EQ(settings.reflection.rayCast, passes::RayCastRule::WhenCheaper) << "the planner chooses by default";
  v1::RenderSettings update;
  update.set_jpeg_quality(70);
  ASSERT_TRUE(applySettingsUpdate(update, settings));
  EXPECT_EQ(settings.reflection.rayCast, passes::RayCastRule::WhenCheaper)
      << "an update that names no search leaves it";
  update.set_search(v1::SEARCH_HIERARCHY);
  ASSERT_TRUE(applySettingsUpdate(update, settings));
  EXPECT_EQ(settings.reflection.search, passes::SearchStrategy::Hierarchy);
  EXPECT_EQ(settings.reflection.rayCast, passes::RayCastRule::Never);
  EXPECT_EQ(settingsToProto(settings).ray_cast(), v1::RAY_CAST_NEVER);
  update.set_ray_cast(v1::RAY_CAST_CHEAPER);  // named beside the search, the rule wins
  ASSERT_TRUE(applySettingsUpdate(update, settings));
  EXPECT_EQ(settings.reflection.rayCast, passes::RayCastRule::WhenCheaper);
  EXPECT_EQ(settingsToProto(settings).ray_cast(), v1::RAY_CAST_CHEAPER);
  v1::RenderSettings always;
  always.set_ray_cast(v1::RAY_CAST_ALWAYS);
  ASSERT_TRUE(applySettingsUpdate(always, settings));
  EXPECT_EQ(settings.reflection.rayCast, passes::RayCastRule::Always);
  v1::RenderSettings unknown;
  unknown.set_ray_cast(static_cast<v1::RayCast>(9));
  const Status refused = applySettingsUpdate(unknown, settings);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("ray_cast"), std::string::npos) << refused.error();
  EXPECT_EQ(settings.reflection.rayCast, passes::RayCastRule::Always) << "a refused update changes nothing";
}

TEST(SettingsProtocol, TheTessellationLevelIsBoundedByTheOneLimit) {
  SessionSettings settings;
  v1::RenderSettings update;
  update.set_level(passes::kMaxTessellationLevel);
  ASSERT_TRUE(applySettingsUpdate(update, settings));
  EXPECT_EQ(settings.reflection.tessellation.maxLevel, passes::kMaxTessellationLevel);
  update.set_level(passes::kMaxTessellationLevel + 1);
  const Status refused = applySettingsUpdate(update, settings);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("[0, " + std::to_string(passes::kMaxTessellationLevel) + "]"), std::string::npos)
      << refused.error();
}

}  // namespace
}  // namespace specula::session
