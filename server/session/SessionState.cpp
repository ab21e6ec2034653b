#include "session/SessionState.h"

#include <algorithm>
#include <cmath>

namespace specula::session {

std::pair<int, int> SessionState::renderSize() const {
  auto scaled = [&](int side) {
    return std::max(1, static_cast<int>(std::lround(static_cast<double>(side) * settings.resolutionScale)));
  };
  return {scaled(width), scaled(height)};
}

}  // namespace specula::session
