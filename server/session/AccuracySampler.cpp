#include "session/AccuracySampler.h"

#include <sys/resource.h>
#include <unistd.h>

#include <ctime>

#include "reference/PixelTracer.h"
#include "reference/RayTracer.h"

namespace specula::session {

namespace {

constexpr int kWorkerNice = 19;  // the lowest priority

// CPU time this thread has used: the estimate's cost, which waiting behind the renderer does not inflate.
double threadCpuMilliseconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return 1e3 * static_cast<double>(now.tv_sec) + 1e-6 * static_cast<double>(now.tv_nsec);
}

// Whether two poses place and shape every object alike (the camera may differ).
bool sameGeometry(const scene::ScenePose& a, const scene::ScenePose& b) {
  return a.objectToWorld == b.objectToWorld && a.morphWeights == b.morphWeights && a.jointMatrices == b.jointMatrices;
}

}  // namespace

Result<std::unique_ptr<AccuracySampler>> AccuracySampler::start(std::shared_ptr<const scene::Scene> scene) {
  auto tracer = reference::RayTracer::create(std::move(scene));
  if (!tracer) return Error{"the accuracy estimate's ray tracer: " + tracer.error()};
  std::unique_ptr<AccuracySampler> sampler(new AccuracySampler());
  sampler->tracer_ = std::move(*tracer);
  sampler->worker_ = std::thread([s = sampler.get()] { s->work(); });
  return sampler;
}

AccuracySampler::~AccuracySampler() { stop(); }

void AccuracySampler::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    pending_.clear();
  }
  ready_.notify_all();
  if (worker_.joinable()) worker_.join();
}

void AccuracySampler::submit(const void* owner, AccuracyJob job, Done done) {
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return;
    std::erase_if(pending_, [&](const Pending& p) { return p.owner == owner; });
    pending_.push_back({owner, std::move(job), std::move(done)});
  }
  ready_.notify_one();
}

void AccuracySampler::forget(const void* owner) {
  std::lock_guard lock(mutex_);
  std::erase_if(pending_, [&](const Pending& p) { return p.owner == owner; });
}

void AccuracySampler::work() {
  // Estimating runs beside rendering, never in its way: on a machine whose cores the renderer keeps busy
  // (software GL), this thread gets what is left. (Linux: a thread's own nice value.)
  setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), kWorkerNice);
  while (true) {
    Pending next;
    {
      std::unique_lock lock(mutex_);
      ready_.wait(lock, [&] { return stopping_ || !pending_.empty(); });
      if (stopping_) break;
      next = std::move(pending_.front());
      pending_.pop_front();
    }
    next.done(estimate(next.job));
  }
  posed_.reset();  // Embree objects before the device, on the thread that used them
}

Result<FrameAccuracy> AccuracySampler::estimate(const AccuracyJob& job) {
  const double start = threadCpuMilliseconds();
  if (!posed_ || !sameGeometry(posedFor_, job.pose)) {
    posed_.reset();
    auto posed = tracer_->posedScene(job.pose);
    if (!posed) return Error{posed.error()};
    posed_ = std::move(*posed);
    posedFor_ = job.pose;
  }
  const RenderOutput& output = *job.output;
  auto tracer = tracer_->pixelTracer(posed_, job.pose.camera, {output.width, output.height, 1, 0, job.samples});
  if (!tracer) return Error{tracer.error()};
  reference::MismatchSampleOptions options;
  options.pixels = job.pixels;
  options.seed = job.frame;
  auto sample = reference::sampleMirrorMismatch(**tracer, {output.rgba, output.width, output.height}, options);
  if (!sample) return Error{sample.error()};
  return FrameAccuracy{job.frame, *sample, threadCpuMilliseconds() - start};
}

void AccuracyWindow::add(const FrameAccuracy& frame) {
  frames_.push_back(frame.sample.mismatch);
  if (frames_.size() > kFrames) frames_.pop_front();
}

reference::ShareEstimate AccuracyWindow::pooled() const {
  std::size_t sampled = 0, hits = 0;
  for (const reference::ShareEstimate& frame : frames_) {
    sampled += frame.sampled;
    hits += frame.hits;
  }
  return reference::wilsonInterval(hits, sampled);
}

}  // namespace specula::session
