#include "session/SettingsProtocol.h"

#include <cmath>
#include <cstdio>
#include <set>

#include <google/protobuf/descriptor.h>

#include "passes/ReflectionSettingsSchema.h"
#include "session/SessionSettingsSchema.h"

namespace specula::session {

namespace {

using google::protobuf::FieldDescriptor;

const FieldDescriptor& fieldOf(const SettingInfo& setting) {
  return *v1::RenderSettings::descriptor()->FindFieldByName(setting.protoField);
}

// A number field's value; 0 means unchanged, and -1 sets 0 where the range holds it.
double numberOf(const v1::RenderSettings& message, const FieldDescriptor& field) {
  const google::protobuf::Reflection& reflection = *message.GetReflection();
  switch (field.cpp_type()) {
    case FieldDescriptor::CPPTYPE_FLOAT: return reflection.GetFloat(message, &field);
    case FieldDescriptor::CPPTYPE_INT32: return reflection.GetInt32(message, &field);
    case FieldDescriptor::CPPTYPE_UINT32: return reflection.GetUInt32(message, &field);
    default: return 0.0;
  }
}

void setNumber(v1::RenderSettings& message, const FieldDescriptor& field, double value) {
  const google::protobuf::Reflection& reflection = *message.GetReflection();
  switch (field.cpp_type()) {
    case FieldDescriptor::CPPTYPE_FLOAT: reflection.SetFloat(&message, &field, static_cast<float>(value)); break;
    case FieldDescriptor::CPPTYPE_INT32: reflection.SetInt32(&message, &field, static_cast<int>(value)); break;
    case FieldDescriptor::CPPTYPE_UINT32:
      reflection.SetUInt32(&message, &field, static_cast<std::uint32_t>(value));
      break;
    default: break;
  }
}

// The value `update` gives the setting (a choice's index, or the number), nullopt when it leaves it
// unchanged, or what is wrong with it.
Result<std::optional<double>> updatedValue(const SettingInfo& setting, const v1::RenderSettings& update) {
  const FieldDescriptor& field = fieldOf(setting);
  const std::string name = "settings: " + std::string(field.name());
  if (field.cpp_type() == FieldDescriptor::CPPTYPE_ENUM) {
    const int number = update.GetReflection()->GetEnumValue(update, &field);
    if (number == 0) return std::optional<double>();
    for (std::size_t i = 0; i < setting.choices.size(); ++i)
      if (field.enum_type()->FindValueByName(setting.choices[i].protoValue)->number() == number)
        return std::optional<double>(static_cast<double>(i));
    return Error{name + " has no value " + std::to_string(number) + "; it takes " + settingRange(setting)};
  }
  double value = numberOf(update, field);
  if (value == 0.0) return std::optional<double>();
  const bool zeroInRange = setting.type != SettingType::Choice && setting.min <= 0.0;
  if (value == -1.0 && zeroInRange) value = 0.0;
  const std::string accepted = settingRange(setting) + (zeroInRange ? " (-1 for 0)" : "");
  char got[32];
  std::snprintf(got, sizeof got, "%g", value);
  if (setting.type == SettingType::Choice) {
    if (auto index = findChoice(setting, got)) return std::optional<double>(*index);
    return Error{name + " must be " + accepted + ", got " + got};
  }
  if (settingProblem(setting, value)) return Error{name + " must lie in " + accepted + ", got " + got};
  return std::optional<double>(value);
}

}  // namespace

v1::RenderSettings settingsToProto(const SessionSettings& settings) {
  v1::RenderSettings out;
  for (const SessionSetting& setting : sessionSettingsSchema()) {
    const SettingInfo& info = setting.info;
    if (info.protoField.empty()) continue;
    const FieldDescriptor& field = fieldOf(info);
    const double value = setting.read(settings);
    if (field.cpp_type() == FieldDescriptor::CPPTYPE_ENUM) {
      const std::string& protoValue = info.choices.at(static_cast<std::size_t>(value)).protoValue;
      out.GetReflection()->SetEnumValue(&out, &field, field.enum_type()->FindValueByName(protoValue)->number());
    } else if (info.type == SettingType::Choice) {
      setNumber(out, field, std::stod(info.choices.at(static_cast<std::size_t>(value)).name));
    } else {
      setNumber(out, field, value == 0.0 ? -1.0 : value);
    }
  }
  return out;
}

Status applySettingsUpdate(const v1::RenderSettings& original, SessionSettings& current) {
  // Protocol 1.0 clients name the refined explosion map as a search strategy of its own.
  v1::RenderSettings update = original;
  if (update.search() == v1::SEARCH_EXPLOSION_MAP_REFINED) {
    update.set_search(v1::SEARCH_EXPLOSION_MAP);
    if (update.explosion_refine() == v1::SWITCH_UNSPECIFIED) update.set_explosion_refine(v1::SWITCH_ON);
  }
  SessionSettings settings = current;
  std::set<std::string_view> named;
  for (const SessionSetting& setting : sessionSettingsSchema()) {
    if (setting.info.protoField.empty()) continue;
    auto value = updatedValue(setting.info, update);
    if (!value) return Error{value.error()};
    if (!*value) continue;
    setting.write(settings, **value);
    named.insert(setting.info.name);
  }
  passes::applyImpliedSettings(settings.reflection, [&](std::string_view name) { return named.contains(name); });
  current = settings;
  return {};
}

}  // namespace specula::session
