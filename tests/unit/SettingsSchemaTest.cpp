// Every setting's range and choices are the same on the command line, over the protocol, in the
// validator and in the browser's schema: probes generated from the schema, none listed by hand.
#include <gtest/gtest.h>

#include <google/protobuf/descriptor.h>
#include <nlohmann/json.hpp>
#include <set>

#include "app/ReflectionOptions.h"
#include "passes/ReflectionSettingsSchema.h"
#include "session/SessionSettingsSchema.h"
#include "session/SettingsProtocol.h"

namespace specula {
namespace {

using google::protobuf::FieldDescriptor;
using session::SessionSetting;
using session::SessionSettings;

CommandLine settingsCommandLine() {
  return CommandLine("test", "every session setting",
                     app::settingOptions(session::sessionSettingsSchema(), SessionSettings{}));
}

// What `--name text` does: the value it sets, or the error.
Result<double> throughCommandLine(const SessionSetting& setting, const std::string& text) {
  CommandLine options = settingsCommandLine();
  const std::vector<std::string> arguments = {"--" + setting.info.name, text};
  if (Status parsed = options.parse(arguments); !parsed) return Error{parsed.error()};
  SessionSettings settings;
  if (Status status = app::parseSettingOptions(options, session::sessionSettingsSchema(), {}, settings); !status)
    return Error{status.error()};
  return setting.read(settings);
}

const FieldDescriptor& protoField(const SettingInfo& info) {
  const FieldDescriptor* field = v1::RenderSettings::descriptor()->FindFieldByName(info.protoField);
  if (!field) throw std::logic_error(info.name + " names no RenderSettings field " + info.protoField);
  return *field;
}

// What a RenderSettings update carrying `value` in the setting's field does.
Result<double> throughProtocol(const SessionSetting& setting, double value) {
  const FieldDescriptor& field = protoField(setting.info);
  v1::RenderSettings update;
  const google::protobuf::Reflection& reflection = *update.GetReflection();
  const double sent = value == 0.0 ? -1.0 : value;  // proto3 cannot send 0: -1 stands for it
  switch (field.cpp_type()) {
    case FieldDescriptor::CPPTYPE_FLOAT: reflection.SetFloat(&update, &field, static_cast<float>(sent)); break;
    case FieldDescriptor::CPPTYPE_INT32: reflection.SetInt32(&update, &field, static_cast<int>(sent)); break;
    case FieldDescriptor::CPPTYPE_UINT32:
      reflection.SetUInt32(&update, &field, static_cast<std::uint32_t>(sent));
      break;
    default: throw std::logic_error(setting.info.name + ": not a number field");
  }
  SessionSettings settings;
  if (Status status = session::applySettingsUpdate(update, settings); !status) return Error{status.error()};
  return setting.read(settings);
}

// Values on both sides of each end of the range, inside it, and a fraction for integers.
std::vector<double> probes(const SettingInfo& info) {
  const double step = info.type == SettingType::Integer ? 1.0 : (info.max - info.min) * 1e-3;
  std::vector<double> values = {info.min, info.max, info.min - step, info.max + step, (info.min + info.max) / 2};
  if (info.type == SettingType::Integer) values.push_back(info.min + 0.5);
  return values;
}

bool inRange(const SettingInfo& info, double value) {
  return value >= info.min && value <= info.max && (info.type != SettingType::Integer || value == std::floor(value));
}

std::string text(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", value);
  return buffer;
}

TEST(SettingsSchema, NumbersHaveTheSameRangeOnTheCommandLineTheProtocolAndTheValidator) {
  int probed = 0;
  for (const SessionSetting& setting : session::sessionSettingsSchema()) {
    const SettingInfo& info = setting.info;
    if (info.type == SettingType::Choice) continue;
    for (double value : probes(info)) {
      SCOPED_TRACE(info.name + " = " + text(value));
      const bool valid = inRange(info, value);
      const Result<double> cli = throughCommandLine(setting, text(value));
      EXPECT_EQ(static_cast<bool>(cli), valid) << (cli ? "accepted" : cli.error());
      if (cli) {
        EXPECT_FLOAT_EQ(static_cast<float>(*cli), static_cast<float>(value));
      }
      if (!cli) {
        EXPECT_NE(cli.error().find("--" + info.name), std::string::npos) << cli.error();
      }
      EXPECT_EQ(static_cast<bool>(settingProblem(info, value)), !valid);
      if (!info.protoField.empty()) {
        // What the wire cannot say: fractions in integer fields, negatives in unsigned ones, 0 where 0
        // means unchanged, and -1 where -1 means 0.
        const FieldDescriptor::CppType type = protoField(info).cpp_type();
        if (type != FieldDescriptor::CPPTYPE_FLOAT && value != std::floor(value)) continue;
        if (type == FieldDescriptor::CPPTYPE_UINT32 && value < 0.0) continue;
        if (value == 0.0 && info.min > 0.0) continue;
        if (value == -1.0 && info.min <= 0.0) continue;
        const Result<double> wire = throughProtocol(setting, value);
        EXPECT_EQ(static_cast<bool>(wire), valid) << (wire ? "accepted" : wire.error());
        if (wire) {
          EXPECT_FLOAT_EQ(static_cast<float>(*wire), static_cast<float>(value));
        }
        if (!wire) {
          EXPECT_NE(wire.error().find(info.protoField), std::string::npos) << wire.error();
        }
      }
      ++probed;
    }
  }
  EXPECT_GE(probed, 40);
}

TEST(SettingsSchema, ReflectionSettingsOutOfRangeAreWhatTheRendererRefuses) {
  for (const passes::ReflectionSetting& setting : passes::reflectionSettingsSchema()) {
    const SettingInfo& info = setting.info;
    if (info.type == SettingType::Choice) continue;
    for (double value : probes(info)) {
      passes::ReflectionSettings settings;
      setting.write(settings, value);
      const auto problem = passes::reflectionSettingsProblem(settings);
      // An integer member truncates what is written to it: the renderer sees the truncated value.
      EXPECT_EQ(static_cast<bool>(problem), !inRange(info, setting.read(settings))) << info.name << " = " << value;
      if (problem) {
        EXPECT_NE(problem->find(info.name), std::string::npos) << *problem;
      }
    }
  }
}

TEST(SettingsSchema, ChoicesAreTheSameOnTheCommandLineAndTheProtocolAndRoundTrip) {
  for (const SessionSetting& setting : session::sessionSettingsSchema()) {
    const SettingInfo& info = setting.info;
    if (info.type != SettingType::Choice) continue;
    SCOPED_TRACE(info.name);
    ASSERT_GE(info.choices.size(), 2u);
    for (std::size_t index = 0; index < info.choices.size(); ++index) {
      const Result<double> cli = throughCommandLine(setting, info.choices[index].name);
      ASSERT_TRUE(cli) << cli.error();
      EXPECT_EQ(*cli, static_cast<double>(index));
      if (info.protoField.empty()) continue;
      // The protocol sends what the command line set, and reading it back sets the same choice.
      SessionSettings settings;
      setting.write(settings, static_cast<double>(index));
      const v1::RenderSettings sent = session::settingsToProto(settings);
      SessionSettings received;
      ASSERT_TRUE(session::applySettingsUpdate(sent, received));
      EXPECT_EQ(setting.read(received), static_cast<double>(index)) << info.choices[index].name;
    }
    const Result<double> bogus = throughCommandLine(setting, "bogus");
    ASSERT_FALSE(bogus);
    EXPECT_NE(bogus.error().find(settingRange(info)), std::string::npos) << bogus.error();
    if (info.protoField.empty()) continue;
    const FieldDescriptor& field = protoField(info);
    if (field.cpp_type() != FieldDescriptor::CPPTYPE_ENUM) continue;
    v1::RenderSettings unknown;
    unknown.GetReflection()->SetEnumValue(&unknown, &field, 99);
    SessionSettings settings;
    const Status refused = session::applySettingsUpdate(unknown, settings);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().find(info.protoField), std::string::npos) << refused.error();
  }
}

TEST(SettingsSchema, EveryRenderSettingsFieldBelongsToOneSetting) {
  std::set<std::string> claimed;
  for (const SessionSetting& setting : session::sessionSettingsSchema())
    if (!setting.info.protoField.empty()) {
      protoField(setting.info);
      EXPECT_TRUE(claimed.insert(setting.info.protoField).second) << setting.info.protoField << " claimed twice";
    }
  const google::protobuf::Descriptor& message = *v1::RenderSettings::descriptor();
  for (int i = 0; i < message.field_count(); ++i) {
    const std::string name(message.field(i)->name());
    if (name == "sequence" || name == "client_time_ms") continue;  // input bookkeeping, not a setting
    EXPECT_TRUE(claimed.contains(name)) << name << " is on the wire but in no schema";
  }
}

TEST(SettingsSchema, TheBrowsersSchemaCarriesTheSameRangesAndChoices) {
  const nlohmann::json schema = nlohmann::json::parse(session::settingsSchemaJson(SessionSettings{}));
  std::size_t carried = 0;
  for (const SessionSetting& setting : session::sessionSettingsSchema()) {
    const SettingInfo& info = setting.info;
    if (info.protoField.empty()) continue;
    const auto entry = std::find_if(schema["settings"].begin(), schema["settings"].end(),
                                    [&](const nlohmann::json& e) { return e["name"] == info.name; });
    ASSERT_NE(entry, schema["settings"].end()) << info.name;
    ++carried;
    EXPECT_EQ((*entry)["field"], protoField(info).json_name());
    EXPECT_EQ((*entry)["default"], settingText(info, setting.read(SessionSettings{})));
    if (info.type == SettingType::Choice) {
      ASSERT_EQ((*entry)["choices"].size(), info.choices.size()) << info.name;
      for (std::size_t i = 0; i < info.choices.size(); ++i)
        EXPECT_EQ((*entry)["choices"][i]["name"], info.choices[i].name);
    } else {
      EXPECT_EQ((*entry)["min"], info.min);
      EXPECT_EQ((*entry)["max"], info.max);
    }
  }
  EXPECT_EQ(carried, schema["settings"].size());
}

TEST(SettingsSchema, ANamedSearchAndAnAngleMetricSetTheirDependentsOnEveryInterface) {
  CommandLine options = settingsCommandLine();
  const std::vector<std::string> arguments = {"--search", "hierarchy", "--metric", "angle"};
  ASSERT_TRUE(options.parse(arguments));
  SessionSettings cli;
  ASSERT_TRUE(app::parseSettingOptions(options, session::sessionSettingsSchema(), {}, cli));
  app::applyImpliedOptions(options, cli.reflection);
  v1::RenderSettings update;
  update.set_search(v1::SEARCH_HIERARCHY);
  update.set_metric(v1::METRIC_ANGLE);
  SessionSettings wire;
  ASSERT_TRUE(session::applySettingsUpdate(update, wire));
  for (const SessionSettings* settings : {&cli, &wire}) {
    EXPECT_EQ(settings->reflection.rayCast, passes::RayCastRule::Never);
    EXPECT_LT(settings->reflection.tessellation.threshold, 0.01f) << "an angle threshold, not a pixel one";
  }
  EXPECT_TRUE(cli.reflection == wire.reflection);
}

}  // namespace
}  // namespace specula
