#pragma once
// An accuracy target for a session: from a ladder of reflection settings the accuracy report measures,
// ordered from the least to the most accurate, the session renders the cheapest whose live estimate
// (AccuracyWindow) keeps the mirror mismatch under the target. It moves up as soon as the window's
// estimate exceeds the target, and down only after the window's 95 % upper bound has stayed under half
// the target for a full window, never back onto a setting that failed within its cool-down.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "passes/ReflectionSettings.h"
#include "reference/MismatchSample.h"

namespace specula::session {

struct AccuracyRung {
  std::string name;
  passes::ReflectionSettings settings;
  bool exact = false;  // exact by construction: meets any target
};

// The session's own settings `base`, and around it: the environment map (cheapest, off where the
// surroundings are near), the search without tessellation, `base` itself, and every mirror ray-cast
// (exact). Settings equal to a rung already listed are left out.
std::vector<AccuracyRung> accuracyLadder(const passes::ReflectionSettings& base);

class AccuracyController {
 public:
  // Frames a window must hold before a setting is judged to meet the target (and may step down).
  static constexpr std::size_t kSettleFrames = 8;
  // Frames a setting that failed is not tried again; doubled at each further failure, to kMaxCooldown.
  static constexpr std::uint64_t kCooldownFrames = 60, kMaxCooldownFrames = 960;

  // Starts on the most accurate rung; `target` is a share in (0, 1].
  AccuracyController(std::vector<AccuracyRung> ladder, double target);

  const AccuracyRung& current() const { return ladder_[rung_]; }
  std::size_t rung() const { return rung_; }
  double target() const { return target_; }
  const std::string& reason() const { return reason_; }
  bool met() const { return met_; }

  // A frame of rung `rung` took `milliseconds` to render: its cost, a moving average.
  void frameRendered(std::size_t rung, double milliseconds);
  // The current rung's window after a new estimate (`frame` counts the session's frames). Returns true
  // when the rung changed: the caller starts a new window.
  bool windowMeasured(const reference::ShareEstimate& window, std::size_t windowFrames, std::uint64_t frame);

 private:
  struct RungState {
    double costMs = 0.0;  // 0: not measured yet
    std::uint64_t failedAt = 0;
    std::uint64_t cooldown = 0;  // 0: never failed
  };
  void moveTo(std::size_t rung, std::string reason);
  std::string percent(double share) const;

  std::vector<AccuracyRung> ladder_;
  std::vector<RungState> states_;
  double target_;
  std::size_t rung_;
  std::string reason_;
  bool met_ = true;
};

}  // namespace specula::session
