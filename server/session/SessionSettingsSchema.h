#pragma once
// Every setting of a session, declared once: the reflection settings (passes/ReflectionSettingsSchema)
// and how frames are streamed. The protocol (SettingsProtocol), `specula serve`'s session defaults and
// the browser's settings panel (GET /settings-schema.json) are derived from this table.
#include <string>
#include <string_view>
#include <vector>

#include "base/SettingSchema.h"
#include "session/SessionState.h"

namespace specula::session {

using SessionSetting = Setting<SessionSettings>;

inline constexpr std::string_view kStreamGroup = "stream";

const std::vector<SessionSetting>& sessionSettingsSchema();

// The schema as JSON for the browser: each setting's name, group, type, help, choices (with their
// protocol values), range, protocol field (its proto3 JSON name) and the value in `defaults`.
std::string settingsSchemaJson(const SessionSettings& defaults);

}  // namespace specula::session
