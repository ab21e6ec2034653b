#include "session/SessionSettingsSchema.h"

#include <algorithm>

#include <google/protobuf/descriptor.h>
#include <nlohmann/json.hpp>

#include "math/SamplePattern.h"
#include "passes/ReflectionSettingsSchema.h"
#include "specula.pb.h"

namespace specula::session {

namespace {

SessionSetting integer(std::string name, std::string protoField, std::string help, int min, int max,
                       int SessionSettings::*member) {
  return {numberSetting(kStreamGroup, SettingType::Integer, std::move(name), "N", std::move(help), min, max,
                        std::move(protoField)),
          [member](const SessionSettings& s) { return static_cast<double>(s.*member); },
          [member](SessionSettings& s, double value) { s.*member = static_cast<int>(value); }};
}

// Anti-aliasing samples a pixel: the counts math::samplePattern has patterns for.
SessionSetting samples(std::string name, std::string protoField, std::string help, int SessionSettings::*member) {
  SettingInfo info = choiceSetting(kStreamGroup, std::move(name), std::move(help), {}, std::move(protoField));
  std::vector<int> counts;
  for (int count = 1; count <= 16; ++count)
    if (!math::sampleCountProblem(count)) {
      counts.push_back(count);
      info.choices.push_back({std::to_string(count), "", ""});
    }
  return {
      std::move(info),
      [member, counts](const SessionSettings& s) {
        return static_cast<double>(std::find(counts.begin(), counts.end(), s.*member) - counts.begin());
      },
      [member, counts](SessionSettings& s, double index) { s.*member = counts.at(static_cast<std::size_t>(index)); }};
}

std::vector<SessionSetting> declareSettings() {
  std::vector<SessionSetting> settings;
  for (const passes::ReflectionSetting& setting : passes::reflectionSettingsSchema())
    settings.push_back({setting.info, [read = setting.read](const SessionSettings& s) { return read(s.reflection); },
                        [write = setting.write](SessionSettings& s, double value) { write(s.reflection, value); }});
  settings.push_back({numberSetting(kStreamGroup, SettingType::Number, "resolution-scale", "X",
                                    "frames are rendered this much smaller and scaled up by the client", 0.05, 1.0,
                                    "resolution_scale"),
                      [](const SessionSettings& s) { return static_cast<double>(s.resolutionScale); },
                      [](SessionSettings& s, double value) { s.resolutionScale = static_cast<float>(value); }});
  settings.push_back(
      integer("jpeg-quality", "jpeg_quality", "JPEG quality of still frames", 1, 100, &SessionSettings::jpegQuality));
  settings.push_back(integer("interactive-quality", "interactive_quality",
                             "JPEG quality of frames sent while input arrives", 1, 100,
                             &SessionSettings::interactiveQuality));
  settings.push_back(samples("still-samples", "still_samples", "anti-aliasing of still frames: samples a pixel",
                             &SessionSettings::stillSamples));
  settings.push_back(samples("interactive-samples", "interactive_samples",
                             "anti-aliasing of frames sent while input arrives", &SessionSettings::interactiveSamples));
  settings.push_back(integer("accuracy-samples", "accuracy_samples",
                             "mirror pixels of each frame the reference ray tracer traces for the live accuracy "
                             "estimate (0: no estimate)",
                             0, reference::kMaxAccuracySamples, &SessionSettings::accuracySamples));
  settings.push_back({numberSetting(kStreamGroup, SettingType::Number, "accuracy-target", "P",
                                    "percent of mirror pixels allowed wrong: each frame renders the cheapest setting "
                                    "whose live estimate stays under it (0: the reflection settings as given; needs "
                                    "accuracy-samples)",
                                    0.0, 100.0, "accuracy_target"),
                      [](const SessionSettings& s) { return static_cast<double>(s.accuracyTarget); },
                      [](SessionSettings& s, double value) { s.accuracyTarget = static_cast<float>(value); }});
  return settings;
}

}  // namespace

const std::vector<SessionSetting>& sessionSettingsSchema() {
  static const std::vector<SessionSetting> schema = declareSettings();
  return schema;
}

std::string settingsSchemaJson(const SessionSettings& defaults) {
  const google::protobuf::Descriptor* message = v1::RenderSettings::descriptor();
  nlohmann::json settings = nlohmann::json::array();
  for (const SessionSetting& setting : sessionSettingsSchema()) {
    const SettingInfo& info = setting.info;
    if (info.protoField.empty()) continue;  // the browser can only change what the protocol carries
    nlohmann::json entry = {{"name", info.name},
                            {"group", info.group},
                            {"help", info.help},
                            {"field", message->FindFieldByName(info.protoField)->json_name()},
                            {"default", settingText(info, setting.read(defaults))}};
    if (info.type == SettingType::Choice) {
      entry["type"] = "choice";
      for (const SettingChoice& choice : info.choices)
        entry["choices"].push_back({{"name", choice.name}, {"help", choice.help}, {"value", choice.protoValue}});
    } else {
      entry["type"] = info.type == SettingType::Integer ? "integer" : "number";
      entry["min"] = info.min;
      entry["max"] = info.max;
    }
    settings.push_back(std::move(entry));
  }
  return nlohmann::json{{"settings", settings}}.dump(1);
}

}  // namespace specula::session
