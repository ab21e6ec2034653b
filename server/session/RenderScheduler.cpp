#include "session/RenderScheduler.h"

#include <algorithm>

#include "encode/JpegEncoder.h"
#include "session/Session.h"

namespace specula::session {

struct RenderScheduler::EncodeJob {
  std::shared_ptr<Session> session;
  FrameRequest request;
  std::shared_ptr<const RenderOutput> output;
};

Result<std::unique_ptr<RenderScheduler>> RenderScheduler::start(FrameRendererFactory factory,
                                                                SchedulerOptions options) {
  std::unique_ptr<RenderScheduler> scheduler(new RenderScheduler());
  const int renderThreads = std::max(1, options.renderThreads);
  for (int i = 0; i < renderThreads; ++i)
    scheduler->threads_.emplace_back([s = scheduler.get(), factory] { s->renderLoop(factory); });
  for (int i = 0; i < std::max(1, options.encodeThreads); ++i)
    scheduler->threads_.emplace_back([s = scheduler.get()] { s->encodeLoop(); });
  std::string error;
  {
    std::unique_lock lock(scheduler->mutex_);
    scheduler->changed_.wait(
        lock, [&] { return scheduler->renderersReady_ == renderThreads || !scheduler->startupError_.empty(); });
    error = scheduler->startupError_;
  }
  if (!error.empty()) return Error{error};  // the destructor joins the threads
  return scheduler;
}

RenderScheduler::~RenderScheduler() { stop(); }

void RenderScheduler::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    sessions_.clear();
  }
  {
    std::lock_guard lock(encodeMutex_);
    encodersStopping_ = true;
    encodeQueue_.clear();
  }
  changed_.notify_all();
  encodeReady_.notify_all();
  for (std::thread& thread : threads_)
    if (thread.joinable()) thread.join();
  std::lock_guard lock(encodeMutex_);
  encodeQueue_.clear();  // a worker may have queued one while stopping
}

void RenderScheduler::add(std::shared_ptr<Session> session) {
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return;
    sessions_.push_back(std::move(session));
    ++generation_;
  }
  changed_.notify_all();
}

void RenderScheduler::remove(const Session* session) {
  std::lock_guard lock(mutex_);
  std::erase_if(sessions_, [&](const auto& s) { return s.get() == session; });
}

void RenderScheduler::wake() {
  {
    std::lock_guard lock(mutex_);
    ++generation_;
  }
  changed_.notify_all();
}

std::size_t RenderScheduler::waitingSessions() {
  const Clock::time_point now = Clock::now();
  std::lock_guard lock(mutex_);
  return static_cast<std::size_t>(
      std::count_if(sessions_.begin(), sessions_.end(), [&](const auto& session) { return session->due(now).now; }));
}

void RenderScheduler::renderLoop(FrameRendererFactory factory) {
  auto renderer = factory();
  {
    std::lock_guard lock(mutex_);
    if (renderer) ++renderersReady_;
    else if (startupError_.empty()) startupError_ = renderer.error();
  }
  changed_.notify_all();
  if (!renderer) return;

  std::unique_lock lock(mutex_);
  while (!stopping_) {
    const Clock::time_point now = Clock::now();
    std::shared_ptr<Session> chosen;
    std::optional<Clock::time_point> wakeAt;
    for (std::size_t k = 0; k < sessions_.size() && !chosen; ++k) {
      const std::size_t i = (next_ + k) % sessions_.size();
      const Session::Due due = sessions_[i]->due(now);
      if (due.now) {
        chosen = sessions_[i];
        next_ = i + 1;  // the next search starts after it: round-robin fairness
      } else if (due.wakeAt && (!wakeAt || *due.wakeAt < *wakeAt)) {
        wakeAt = due.wakeAt;
      }
    }
    if (!chosen) {
      const std::uint64_t seen = generation_;
      auto woken = [&] { return stopping_ || generation_ != seen; };
      if (wakeAt) changed_.wait_until(lock, *wakeAt, woken);
      else changed_.wait(lock, woken);
      continue;
    }
    FrameRequest request = chosen->takeFrame(now);
    lock.unlock();
    std::shared_ptr<const RenderOutput> picture = request.reuse;
    if (!picture) {
      auto output = (*renderer)->render(request.job);
      if (output) picture = std::make_shared<const RenderOutput>(std::move(*output));
      else chosen->renderFailed(request, output.error());
    }
    if (picture) {
      {
        std::lock_guard encodeLock(encodeMutex_);
        encodeQueue_.push_back({chosen, std::move(request), std::move(picture)});
      }
      encodeReady_.notify_one();
    }
    chosen.reset();
    lock.lock();
  }
  lock.unlock();
  renderer->reset();  // destroy GL objects on the thread that owns the context
}

void RenderScheduler::encodeLoop() {
  encode::JpegEncoder encoder;
  while (true) {
    EncodeJob job;
    {
      std::unique_lock lock(encodeMutex_);
      encodeReady_.wait(lock, [&] { return !encodeQueue_.empty() || encodersStopping_; });
      if (encodersStopping_) return;
      job = std::move(encodeQueue_.front());
      encodeQueue_.pop_front();
    }
    const Clock::time_point start = Clock::now();
    auto jpeg =
        encoder.encode({job.output->rgba.data(), job.output->width, job.output->height}, job.request.jpegQuality);
    const double encodeMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    if (!jpeg) {
      job.session->renderFailed(job.request, jpeg.error());
      continue;
    }
    job.session->deliver(job.request, std::move(job.output), std::string(jpeg->begin(), jpeg->end()), encodeMs);
  }
}

}  // namespace specula::session
