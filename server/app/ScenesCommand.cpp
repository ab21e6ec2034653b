// `specula scenes`: lists the built-in scenes with their size, so users know what --scene accepts.
#include <cstdio>
#include <iostream>

#include "base/CommandLine.h"
#include "app/Commands.h"
#include "scene/builtin/BuiltinScenes.h"

namespace specula::app {

int runScenes(std::span<const std::string> arguments) {
  CommandLine options("specula scenes", "Lists the built-in scenes (any of them works as --scene NAME).", {});
  auto fail = [](const std::string& message) {
    std::cerr << "specula scenes: " << message << "\n";
    return 1;
  };
  if (auto exitCode = options.parseOrExit(arguments, fail)) return *exitCode;
  for (std::string_view name : scene::builtinSceneNames()) {
    const scene::Scene scene = *scene::makeBuiltinScene(name);
    std::printf("%-14.*s %7zu vertices %7zu triangles %2zu mirrors  %.*s\n", static_cast<int>(name.size()), name.data(),
                scene.vertexCount(), scene.triangleCount(), scene.mirrorCount(),
                static_cast<int>(scene::builtinSceneSummary(name).size()), scene::builtinSceneSummary(name).data());
  }
  return 0;
}

}  // namespace specula::app
