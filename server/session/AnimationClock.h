#pragma once
// A session's scene clock: plays at a speed, pauses and seeks. Scene time in milliseconds.
#include <chrono>

namespace specula::session {

using Clock = std::chrono::steady_clock;

class AnimationClock {
 public:
  double sceneMs(Clock::time_point now) const;
  bool playing() const { return playing_; }
  float speed() const { return speed_; }

  void play(Clock::time_point now);
  void pause(Clock::time_point now);
  void seek(double sceneMs, Clock::time_point now);
  void setSpeed(float speed, Clock::time_point now);  // scene ms per wall ms; negative runs backwards

 private:
  void reanchor(Clock::time_point now);

  double anchorSceneMs_ = 0.0;  // scene time at anchorWall_
  Clock::time_point anchorWall_{};
  bool playing_ = false;
  float speed_ = 1.0f;
};

}  // namespace specula::session
