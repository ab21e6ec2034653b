#include "base/SettingSchema.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace specula {

namespace {

std::string numberText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

SettingInfo choiceSetting(std::string_view group, std::string name, std::string help,
                          std::vector<SettingChoice> choices, std::string protoField) {
  SettingInfo info;
  info.name = std::move(name);
  info.group = group;
  info.type = SettingType::Choice;
  info.help = std::move(help);
  info.choices = std::move(choices);
  info.protoField = std::move(protoField);
  return info;
}

SettingInfo numberSetting(std::string_view group, SettingType type, std::string name, std::string valueName,
                          std::string help, double min, double max, std::string protoField) {
  SettingInfo info;
  info.name = std::move(name);
  info.group = group;
  info.type = type;
  info.valueName = std::move(valueName);
  info.help = std::move(help);
  info.min = min;
  info.max = max;
  info.protoField = std::move(protoField);
  return info;
}

std::string settingText(const SettingInfo& setting, double value) {
  if (setting.type == SettingType::Choice) {
    const auto index = static_cast<std::size_t>(value);
    return index < setting.choices.size() ? setting.choices[index].name : "?";
  }
  return numberText(value);
}

std::string settingRange(const SettingInfo& setting) {
  if (setting.type != SettingType::Choice) return "[" + numberText(setting.min) + ", " + numberText(setting.max) + "]";
  std::string names;
  for (std::size_t i = 0; i < setting.choices.size(); ++i) {
    if (i > 0) names += i + 1 == setting.choices.size() ? " or " : ", ";
    names += setting.choices[i].name;
  }
  return names;
}

std::optional<int> findChoice(const SettingInfo& setting, std::string_view name) {
  for (std::size_t i = 0; i < setting.choices.size(); ++i)
    if (setting.choices[i].name == name) return static_cast<int>(i);
  return std::nullopt;
}

std::optional<std::string> settingProblem(const SettingInfo& setting, double value) {
  switch (setting.type) {
    case SettingType::Choice:
      if (value >= 0.0 && value < static_cast<double>(setting.choices.size()) && value == std::floor(value))
        return std::nullopt;
      return setting.name + " must be " + settingRange(setting);
    case SettingType::Integer:
      if (value != std::floor(value)) return setting.name + " must be an integer in " + settingRange(setting);
      [[fallthrough]];
    case SettingType::Number:
      if (std::isfinite(value) && value >= setting.min && value <= setting.max) return std::nullopt;
      return setting.name + " must lie in " + settingRange(setting);
  }
  return setting.name + " has an unknown type";
}

Result<double> parseSetting(const SettingInfo& setting, std::string_view text) {
  const auto expected = [&] {
    const std::string what = setting.type == SettingType::Choice    ? settingRange(setting)
                             : setting.type == SettingType::Integer ? "an integer in " + settingRange(setting)
                                                                    : "a number in " + settingRange(setting);
    return Error{setting.name + " expects " + what + ", got '" + std::string(text) + "'"};
  };
  if (setting.type == SettingType::Choice) {
    if (auto index = findChoice(setting, text)) return static_cast<double>(*index);
    return expected();
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || settingProblem(setting, value)) return expected();
  return value;
}

}  // namespace specula
