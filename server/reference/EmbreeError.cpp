#include "reference/EmbreeError.h"

#include <embree3/rtcore.h>

#include <string>

namespace specula::reference {

namespace {

// The error code's name and the usual remedy.
std::string_view describe(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "RTC_ERROR_INVALID_ARGUMENT: a scene value Embree rejects; check the scene with sceneProblem()";
    case RTC_ERROR_INVALID_OPERATION:
      return "RTC_ERROR_INVALID_OPERATION: Embree API misuse; this is a bug in specula_reference";
    case RTC_ERROR_OUT_OF_MEMORY: return "RTC_ERROR_OUT_OF_MEMORY: free memory or render a smaller scene";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "RTC_ERROR_UNSUPPORTED_CPU: Embree 3 needs an x86-64 CPU with SSE2 (or ARM NEON)";
    case RTC_ERROR_CANCELLED: return "RTC_ERROR_CANCELLED: the operation was cancelled";
    case RTC_ERROR_UNKNOWN: break;
  }
  return "RTC_ERROR_UNKNOWN: check that libembree3 and its TBB runtime are installed (docker/install-deps.sh)";
}

}  // namespace

std::optional<Error> embreeFailure(RTCDeviceTy* device, std::string_view doing) {
  const RTCError code = rtcGetDeviceError(device);
  if (code == RTC_ERROR_NONE) return std::nullopt;
  return Error{"Embree: cannot " + std::string(doing) + " (" + std::string(describe(code)) + ")"};
}

}  // namespace specula::reference
