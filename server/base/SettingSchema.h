#pragma once
// A setting declared once — name, type, range or choices, help, protocol field — from which the
// command line, the protocol, the validator, --help and the browser's settings panel are derived.
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/Result.h"

namespace specula {

enum class SettingType {
  Choice,   // one of `choices`; its value is the choice's index
  Number,   // a finite number in [min, max]
  Integer,  // an integer in [min, max]
};

struct SettingChoice {
  std::string name;  // "crack-free": what the command line and the browser send
  std::string help;
  std::string protoValue;  // the protocol enum's value name ("TESSELLATION_CRACK_FREE"); empty for a number field
};

struct SettingInfo {
  std::string name;   // "threshold": --threshold on the command line, the key in the browser's panel
  std::string group;  // "tessellation": commands take settings by group; the browser's panel groups by it
  SettingType type = SettingType::Number;
  std::string valueName;  // "PX", shown by --help; a choice lists its names instead
  std::string help;
  std::vector<SettingChoice> choices;
  double min = 0.0, max = 0.0;  // Number and Integer
  // Where the value travels in v1::RenderSettings; empty: a command-line setting only (it sizes server memory).
  std::string protoField;
  // --help's default when it is not just the default value's text ("1 px; 0.003 for angle").
  std::string defaultText;
};

// A setting bound to the struct that holds it: Choice values are indices into `info.choices`.
template <class Target>
struct Setting {
  SettingInfo info;
  std::function<double(const Target&)> read;
  std::function<void(Target&, double)> write;
};

// A setting of one of `choices`, and a Number or Integer one in [min, max].
SettingInfo choiceSetting(std::string_view group, std::string name, std::string help,
                          std::vector<SettingChoice> choices, std::string protoField = "");
SettingInfo numberSetting(std::string_view group, SettingType type, std::string name, std::string valueName,
                          std::string help, double min, double max, std::string protoField = "");

// The value as the command line writes it: a choice's name, or the number ("0.5", "4").
std::string settingText(const SettingInfo& setting, double value);

// Reads what a command line or a client gives, or says what the setting expects and what it got.
Result<double> parseSetting(const SettingInfo& setting, std::string_view text);

// What is wrong with `value` ("must lie in [0, 16]"), naming the setting; nullopt when it is valid.
std::optional<std::string> settingProblem(const SettingInfo& setting, double value);

// "[0, 16]", "crosshair, hierarchy or explosion-map": what the setting accepts, for messages.
std::string settingRange(const SettingInfo& setting);

// The index of the choice named `name`, if any.
std::optional<int> findChoice(const SettingInfo& setting, std::string_view name);

}  // namespace specula
