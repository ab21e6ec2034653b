#pragma once
// Command-line options derived from the settings schemas (passes/ReflectionSettingsSchema,
// session/SessionSettingsSchema): one option per setting, its range, choices and help from there.
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/CommandLine.h"
#include "base/Result.h"
#include "base/SettingSchema.h"
#include "passes/ReflectionSettings.h"

namespace specula::app {

using SettingGroups = std::initializer_list<std::string_view>;

// --NAME for one setting, `defaultValue` shown as its default, `helpSuffix` after its help.
OptionSpec settingOption(const SettingInfo& setting, double defaultValue, std::string_view helpSuffix = "");
// The value the arguments give the setting, nullopt when they do not name it, or what is wrong.
Result<std::optional<double>> givenSetting(const CommandLine& options, const SettingInfo& setting);
// Whether `setting` is in `groups` (every setting is in an empty list).
bool inGroups(const SettingInfo& setting, SettingGroups groups);

// The options of `schema`'s settings in `groups`.
template <class Target>
std::vector<OptionSpec> settingOptions(const std::vector<Setting<Target>>& schema, const Target& defaults,
                                       SettingGroups groups = {}, std::string_view helpSuffix = "") {
  std::vector<OptionSpec> specs;
  for (const Setting<Target>& setting : schema)
    if (inGroups(setting.info, groups))
      specs.push_back(settingOption(setting.info, setting.read(defaults), helpSuffix));
  return specs;
}

// Writes the settings in `groups` that the arguments name into `target`; the rest keep their values.
template <class Target>
Status parseSettingOptions(const CommandLine& options, const std::vector<Setting<Target>>& schema, SettingGroups groups,
                           Target& target) {
  for (const Setting<Target>& setting : schema) {
    if (!inGroups(setting.info, groups)) continue;
    auto value = givenSetting(options, setting.info);
    if (!value) return Error{value.error()};
    if (*value) setting.write(target, **value);
  }
  return {};
}

// The reflection settings but the method (each command names its own methods): the G-buffer,
// search, plan and tessellation groups.
std::vector<OptionSpec> reflectionOptions();
Result<passes::ReflectionSettings> parseReflectionOptions(const CommandLine& options);

// One group each, for commands that take only those.
std::vector<OptionSpec> tessellationOptions();
Result<passes::TessellationSettings> parseTessellationOptions(const CommandLine& options);
std::vector<OptionSpec> searchOptions();
Status parseSearchOptions(const CommandLine& options, passes::ReflectionSettings& settings);
std::vector<OptionSpec> planOptions();
Status parsePlanOptions(const CommandLine& options, passes::ReflectionSettings& settings);

// The defaults that follow what the arguments name (passes::applyImpliedSettings); `--method
// explosion-map` names the search.
void applyImpliedOptions(const CommandLine& options, passes::ReflectionSettings& settings);

// --samples N: anti-aliasing, rays or jittered frames per pixel (math::samplePattern), `fallback` by default.
OptionSpec samplesOption(int fallback,
                         const std::string& what =
                             "anti-aliasing: samples per pixel, 1, 2, 4, 8 or 16 (every method takes the same points)");
Result<int> parseSamples(const CommandLine& options, const std::string& name = "samples");

}  // namespace specula::app
