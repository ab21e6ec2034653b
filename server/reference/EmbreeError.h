#pragma once
#include <optional>
#include <string_view>

#include "base/Result.h"

struct RTCDeviceTy;

namespace specula::reference {

// The pending Embree error of `device` (null: device creation) as an Error naming what was being done
// and how to fix it, or nullopt when there is none. Clears the pending error.
std::optional<Error> embreeFailure(RTCDeviceTy* device, std::string_view doing);

}  // namespace specula::reference
