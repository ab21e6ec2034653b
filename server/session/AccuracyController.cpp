#include "session/AccuracyController.h"

#include <algorithm>
#include <cstdio>
#include <optional>

namespace specula::session {

namespace {

// The weight of a new frame in a rung's moving average cost.
constexpr double kCostWeight = 0.2;
// A setting counts as cheaper than another below this share of its cost (costs are noisy).
constexpr double kCheaperShare = 0.9;

}  // namespace

std::vector<AccuracyRung> accuracyLadder(const passes::ReflectionSettings& base) {
  passes::ReflectionSettings environmentMap = base;
  environmentMap.method = passes::ReflectionMethod::EnvironmentMap;
  passes::ReflectionSettings untessellated = base;
  untessellated.method = passes::ReflectionMethod::Search;
  untessellated.tessellation.mode = passes::TessellationMode::None;
  untessellated.rayCast = passes::RayCastRule::Never;
  passes::ReflectionSettings searched = base;
  searched.method = passes::ReflectionMethod::Search;
  passes::ReflectionSettings rayCast = base;
  rayCast.method = passes::ReflectionMethod::Search;
  rayCast.rayCast = passes::RayCastRule::Always;
  std::vector<AccuracyRung> ladder;
  for (AccuracyRung rung : {AccuracyRung{"environment map", environmentMap, false},
                            AccuracyRung{"virtual objects without tessellation", untessellated, false},
                            AccuracyRung{"the session's settings", searched, false},
                            AccuracyRung{"every mirror ray-cast", rayCast, true}}) {
    const auto same = [&](const AccuracyRung& other) { return other.settings == rung.settings; };
    if (std::none_of(ladder.begin(), ladder.end(), same)) ladder.push_back(std::move(rung));
  }
  return ladder;
}

AccuracyController::AccuracyController(std::vector<AccuracyRung> ladder, double target)
    : ladder_(std::move(ladder)), states_(ladder_.size()), target_(target), rung_(ladder_.size() - 1) {
  reason_ =
      "starting on the most accurate setting until the estimate says a cheaper one keeps under " + percent(target_);
}

std::string AccuracyController::percent(double share) const {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f %%", 100.0 * share);
  return text;
}

void AccuracyController::frameRendered(std::size_t rung, double milliseconds) {
  if (rung >= states_.size()) return;
  double& cost = states_[rung].costMs;
  cost = cost == 0.0 ? milliseconds : (1.0 - kCostWeight) * cost + kCostWeight * milliseconds;
}

void AccuracyController::moveTo(std::size_t rung, std::string reason) {
  rung_ = rung;
  reason_ = std::move(reason);
}

bool AccuracyController::windowMeasured(const reference::ShareEstimate& window, std::size_t windowFrames,
                                        std::uint64_t frame) {
  if (window.sampled == 0) return false;  // no mirror in view: nothing learnt
  const bool exact = ladder_[rung_].exact;
  // Over the target: at once when the whole interval is over it, else once the window has settled.
  const bool over = window.low > target_ || (windowFrames >= kSettleFrames && window.share() > target_);
  if (over && !exact) {
    RungState& failed = states_[rung_];
    failed.cooldown = failed.cooldown == 0 ? kCooldownFrames : std::min(kMaxCooldownFrames, 2 * failed.cooldown);
    failed.failedAt = frame;
    met_ = true;
    moveTo(rung_ + 1, "the estimate " + percent(window.share()) + " of " + ladder_[rung_].name + " exceeds " +
                          percent(target_) + ": more accurate");
    return true;
  }
  if (over) {  // exact, and still over: nothing meets the target
    met_ = false;
    reason_ = "no setting meets " + percent(target_) + " (the exact one is estimated at " + percent(window.share()) +
              "): rendering the most accurate";
    return false;
  }
  met_ = true;
  // An exact setting measured clearly cheaper than this one meets the target for less.
  const double currentCost = states_[rung_].costMs;
  for (std::size_t r = rung_ + 1; r < ladder_.size(); ++r)
    if (ladder_[r].exact && states_[r].costMs > 0.0 && states_[r].costMs < kCheaperShare * currentCost) {
      moveTo(r, ladder_[r].name + " is exact and was measured cheaper than " + ladder_[rung_].name);
      return true;
    }
  if (windowFrames < kSettleFrames) return false;
  if (window.high >= target_ / 2.0) {
    reason_ = ladder_[rung_].name + ": estimated " + percent(window.share()) + " (95 % ≤ " + percent(window.high) +
              "), under " + percent(target_);
    return false;
  }
  // Comfortably under: the cheapest less accurate rung out of its cool-down and not known to cost more.
  std::optional<std::size_t> cheaper;
  for (std::size_t r = 0; r < rung_; ++r) {
    const RungState& state = states_[r];
    if (state.cooldown > 0 && frame < state.failedAt + state.cooldown) continue;
    if (state.costMs > 0.0 && currentCost > 0.0 && state.costMs >= currentCost) continue;
    if (!cheaper || (state.costMs > 0.0 && states_[*cheaper].costMs > 0.0 && state.costMs < states_[*cheaper].costMs))
      cheaper = r;
  }
  if (!cheaper) {
    reason_ = ladder_[rung_].name + ": estimated " + percent(window.share()) + " (95 % ≤ " + percent(window.high) +
              "), the cheapest setting known to meet " + percent(target_);
    return false;
  }
  moveTo(*cheaper, "the estimate of " + ladder_[rung_].name + " stayed under half of " + percent(target_) +
                       " (95 % ≤ " + percent(window.high) + "): trying " + ladder_[*cheaper].name);
  return true;
}

}  // namespace specula::session
