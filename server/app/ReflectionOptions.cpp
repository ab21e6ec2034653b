#include "app/ReflectionOptions.h"

#include <algorithm>

#include "math/SamplePattern.h"
#include "passes/ReflectionSettingsSchema.h"

namespace specula::app {

namespace {

constexpr SettingGroups kCommandGroups = {passes::kGBufferGroup, passes::kSearchGroup, passes::kPlanGroup,
                                          passes::kTessellationGroup};

template <class Settings>
Status parseGroups(const CommandLine& options, SettingGroups groups, Settings& settings) {
  if (Status status = parseSettingOptions(options, passes::reflectionSettingsSchema(), groups, settings); !status)
    return status;
  applyImpliedOptions(options, settings);
  return {};
}

}  // namespace

OptionSpec settingOption(const SettingInfo& setting, double defaultValue, std::string_view helpSuffix) {
  std::string help = setting.help;
  std::string valueName = setting.valueName;
  if (setting.type == SettingType::Choice) {
    valueName.clear();
    std::string separator = ": ";
    for (const SettingChoice& choice : setting.choices) {
      valueName += (valueName.empty() ? "" : "|") + choice.name;
      if (choice.help.empty()) continue;
      help += separator + choice.name + " (" + choice.help + ")";
      separator = "; ";
    }
  } else {
    help += ", in " + settingRange(setting);
  }
  help += helpSuffix;
  return {setting.name, valueName, help,
          setting.defaultText.empty() ? settingText(setting, defaultValue) : setting.defaultText};
}

Result<std::optional<double>> givenSetting(const CommandLine& options, const SettingInfo& setting) {
  if (!options.has(setting.name)) return std::optional<double>();
  auto value = parseSetting(setting, options.text(setting.name));
  if (!value) return Error{"--" + value.error()};
  return std::optional<double>(*value);
}

bool inGroups(const SettingInfo& setting, SettingGroups groups) {
  return groups.size() == 0 || std::find(groups.begin(), groups.end(), setting.group) != groups.end();
}

void applyImpliedOptions(const CommandLine& options, passes::ReflectionSettings& settings) {
  passes::applyImpliedSettings(settings, [&](std::string_view name) {
    const auto given = [&](const std::string& option) { return options.declares(option) && options.has(option); };
    if (name == "search" && given("method") && options.text("method") == "explosion-map") return true;
    return given(std::string(name));
  });
}

std::vector<OptionSpec> reflectionOptions() {
  return settingOptions(passes::reflectionSettingsSchema(), passes::ReflectionSettings{}, kCommandGroups);
}

Result<passes::ReflectionSettings> parseReflectionOptions(const CommandLine& options) {
  passes::ReflectionSettings settings;
  if (Status status = parseGroups(options, kCommandGroups, settings); !status) return Error{status.error()};
  return settings;
}

std::vector<OptionSpec> tessellationOptions() {
  return settingOptions(passes::reflectionSettingsSchema(), passes::ReflectionSettings{}, {passes::kTessellationGroup});
}

Result<passes::TessellationSettings> parseTessellationOptions(const CommandLine& options) {
  passes::ReflectionSettings settings;
  if (Status status = parseGroups(options, {passes::kTessellationGroup}, settings); !status)
    return Error{status.error()};
  return settings.tessellation;
}

std::vector<OptionSpec> searchOptions() {
  return settingOptions(passes::reflectionSettingsSchema(), passes::ReflectionSettings{}, {passes::kSearchGroup});
}

Status parseSearchOptions(const CommandLine& options, passes::ReflectionSettings& settings) {
  return parseGroups(options, {passes::kSearchGroup}, settings);
}

std::vector<OptionSpec> planOptions() {
  return settingOptions(passes::reflectionSettingsSchema(), passes::ReflectionSettings{}, {passes::kPlanGroup});
}

Status parsePlanOptions(const CommandLine& options, passes::ReflectionSettings& settings) {
  return parseGroups(options, {passes::kPlanGroup}, settings);
}

OptionSpec samplesOption(int fallback, const std::string& what) {
  return {"samples", "N", what, std::to_string(fallback)};
}

Result<int> parseSamples(const CommandLine& options, const std::string& name) {
  auto samples = options.integer(name, 1, 16);
  if (!samples) return Error{samples.error()};
  if (auto problem = math::sampleCountProblem(*samples)) return Error{"--" + name + ": " + *problem};
  return *samples;
}

}  // namespace specula::app
