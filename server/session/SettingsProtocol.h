#pragma once
// A session's render settings on the wire (v1::RenderSettings): sent in Welcome, changed by Settings
// messages, carried in signed resume tokens.
#include "base/Result.h"
#include "session/SessionState.h"
#include "specula.pb.h"

namespace specula::session {

// Every field set.
v1::RenderSettings settingsToProto(const SessionSettings& settings);

// Applies the fields `update` sets (zero / UNSPECIFIED keep the current value) to `current`, all or
// nothing: an out-of-range field leaves `current` as it was and says which and what it accepts.
Status applySettingsUpdate(const v1::RenderSettings& update, SessionSettings& current);

}  // namespace specula::session
