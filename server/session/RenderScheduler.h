#pragma once
// Render workers (each owns a renderer and its GL context) and JPEG encoder threads. Workers serve
// sessions round-robin, one frame per session at a time, only when the session says a frame is due.
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "base/Result.h"
#include "session/FrameRenderer.h"

namespace specula::session {

class Session;
struct FrameRequest;

struct SchedulerOptions {
  int renderThreads = 1;  // one GL context each
  int encodeThreads = 1;
};

class RenderScheduler {
 public:
  // Starts the threads and waits until every worker has created its renderer (or one failed).
  static Result<std::unique_ptr<RenderScheduler>> start(FrameRendererFactory factory, SchedulerOptions options);
  ~RenderScheduler();  // stop()

  void add(std::shared_ptr<Session> session);
  void remove(const Session* session);
  void wake();                    // something changed: look for due sessions again
  std::size_t waitingSessions();  // sessions due a frame now that no worker is rendering yet
  void stop();                    // joins every thread; frames in progress are dropped

 private:
  struct EncodeJob;
  RenderScheduler() = default;
  void renderLoop(FrameRendererFactory factory);
  void encodeLoop();

  std::mutex mutex_;  // guards sessions_, next_, generation_, stopping_, startup counts
  std::condition_variable changed_;
  std::vector<std::shared_ptr<Session>> sessions_;
  std::size_t next_ = 0;  // round-robin position
  std::uint64_t generation_ = 0;
  bool stopping_ = false;
  int renderersReady_ = 0;
  std::string startupError_;

  std::mutex encodeMutex_;
  std::condition_variable encodeReady_;
  std::deque<EncodeJob> encodeQueue_;
  bool encodersStopping_ = false;

  std::vector<std::thread> threads_;
};

}  // namespace specula::session
