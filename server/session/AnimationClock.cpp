#include "session/AnimationClock.h"

namespace specula::session {

double AnimationClock::sceneMs(Clock::time_point now) const {
  if (!playing_) return anchorSceneMs_;
  return anchorSceneMs_ + std::chrono::duration<double, std::milli>(now - anchorWall_).count() * speed_;
}

void AnimationClock::reanchor(Clock::time_point now) {
  anchorSceneMs_ = sceneMs(now);
  anchorWall_ = now;
}

void AnimationClock::play(Clock::time_point now) {
  reanchor(now);
  playing_ = true;
}

void AnimationClock::pause(Clock::time_point now) {
  reanchor(now);
  playing_ = false;
}

void AnimationClock::seek(double sceneMs, Clock::time_point now) {
  anchorSceneMs_ = sceneMs;
  anchorWall_ = now;
}

void AnimationClock::setSpeed(float speed, Clock::time_point now) {
  reanchor(now);
  speed_ = speed;
}

}  // namespace specula::session
