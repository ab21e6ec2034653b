#pragma once
// A GL context and a renderer for one built-in scene, as the GL tests use them.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "gl/GlContext.h"
#include "render/Renderer.h"
#include "scene/builtin/BuiltinScenes.h"

namespace specula::testing {

// Default settings, but every visible mirror is searched and drawn as virtual objects: the planner
// would ray-cast a mirror this small on screen, and these tests are about the search.
inline passes::ReflectionSettings virtualObjects(passes::ReflectionSettings settings = {}) {
  settings.rayCastPixels = 0;
  return settings;
}

struct Rig {
  std::unique_ptr<gl::GlContext> context;
  std::unique_ptr<render::Renderer> renderer;
};

// Fails the calling test (not fatally) and returns an empty rig when GL or the scene cannot start.
inline Rig makeRig(const std::string& sceneName) {
  auto context = gl::GlContext::create(gl::PlatformChoice::Auto);
  EXPECT_TRUE(context) << context.error();
  if (!context) return {};
  auto renderer = render::Renderer::create(**context, std::make_shared<const scene::Scene>(*scene::makeBuiltinScene(sceneName)));
  EXPECT_TRUE(renderer) << renderer.error();
  if (!renderer) return {};
  return {std::move(context.value()), std::move(renderer.value())};
}

}  // namespace specula::testing
