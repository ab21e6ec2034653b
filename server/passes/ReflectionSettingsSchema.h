#pragma once
// Every reflection setting, declared once (base/SettingSchema.h): the command line, the protocol,
// reflectionSettingsProblem(), --help and the browser's settings panel all read this table.
#include <functional>
#include <string_view>
#include <vector>

#include "base/SettingSchema.h"
#include "passes/ReflectionSettings.h"

namespace specula::passes {

using ReflectionSetting = Setting<ReflectionSettings>;

// Groups, in the order --help and the browser's panel show them.
inline constexpr std::string_view kMethodGroup = "method", kGBufferGroup = "gbuffer", kSearchGroup = "search",
                                  kPlanGroup = "plan", kTessellationGroup = "tessellation";

const std::vector<ReflectionSetting>& reflectionSettingsSchema();

// Defaults that follow a setting the user named, where they did not name the dependent one too:
// a named search runs (ray-cast never), and the angle metric gets a threshold on its own scale.
void applyImpliedSettings(ReflectionSettings& settings, const std::function<bool(std::string_view name)>& named);

}  // namespace specula::passes
