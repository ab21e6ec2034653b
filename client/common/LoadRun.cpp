#include "LoadRun.h"

#include "OrbitCamera.h"
#include "base/Percentile.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <nlohmann/json.hpp>
#include <numeric>
#include <thread>

namespace specula::client {

namespace {

using Clock = std::chrono::steady_clock;

// The scene's default camera as an orbit, phase-shifted so sessions look from different sides.
OrbitCamera orbitFor(const v1::SceneInfo& scene, int session, int sessions) {
  v1::CameraUpdate camera;
  *camera.mutable_eye() = scene.eye();
  *camera.mutable_target() = scene.target();
  *camera.mutable_up() = scene.up();
  camera.set_fov_degrees(scene.fov_degrees());
  OrbitCamera orbit = OrbitCamera::from(camera);
  orbit.orbit(6.2831853f * static_cast<float>(session) / static_cast<float>(std::max(1, sessions)), 0.0f);
  return orbit;
}

SessionLoad runSession(const LoadOptions& options, int index, Clock::time_point measureFrom, Clock::time_point end,
                       std::atomic<std::uint64_t>& framesSoFar) {
  SessionLoad result;
  v1::Hello hello;
  hello.set_protocol_version(1);
  hello.set_width(static_cast<std::uint32_t>(options.width));
  hello.set_height(static_cast<std::uint32_t>(options.height));
  auto connected =
      ResumingClient::connect(options.address, options.encoding, hello,
                              options.sessionReconnect ? options.sessionReconnect(index) : options.reconnect);
  if (!connected) {
    result.error = connected.error();
    return result;
  }
  ResumingClient& client = **connected;
  std::optional<OrbitCamera> start;  // the session's orbit at time 0, once the welcome names the scene
  const auto inputInterval =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / options.inputHz));
  Clock::time_point nextInput = Clock::now();
  const Clock::time_point began = Clock::now();
  std::uint64_t sequence = 0;
  double renderSum = 0.0, encodeSum = 0.0, serverSum = 0.0, mismatchSum = 0.0, accuracyMsSum = 0.0;
  std::uint64_t lastEstimated = 0;  // Frame.number of the last estimate counted: frames repeat it until the next
  std::optional<Clock::time_point> lastFrame;
  while (Clock::now() < end) {
    if (options.script) {
      const double sinceRunBegan = std::chrono::duration<double>(Clock::now() - (measureFrom - options.warmup)).count();
      if (Status acted = options.script(index, sinceRunBegan, client); !acted) {
        result.error = acted.error();
        break;
      }
    }
    if (start && Clock::now() >= nextInput) {
      const double seconds = std::chrono::duration<double>(Clock::now() - began).count();
      OrbitCamera orbit = *start;
      orbit.orbit(static_cast<float>(seconds * options.orbitDegreesPerSecond * 3.14159265358979 / 180.0), 0.0f);
      if (Status sent = client.send(orbit.message(++sequence, steadyMilliseconds())); !sent) {
        result.error = sent.error();
        break;
      }
      nextInput += inputInterval;
    }
    const auto wait =
        std::chrono::duration_cast<std::chrono::milliseconds>(std::min(end, start ? nextInput : end) - Clock::now());
    auto message = client.receive(std::max(std::chrono::milliseconds(1), wait));
    if (!message) {
      if (client.closeInfo()) {
        result.error =
            "server closed the session: " + std::to_string(client.closeInfo()->code) + " " + client.closeInfo()->reason;
        break;
      }
      continue;  // timed out: time for the next input
    }
    if (message->has_welcome()) {
      start = orbitFor(message->welcome().scene(), index, options.sessions);
      result.resumed += message->welcome().resumed() ? 1 : 0;
    }
    if (message->has_error() && message->error().code() == v1::Error::RESUME_REFUSED) {
      ++result.resumesRefused;  // a fresh session after a reconnect: the orbit goes on
      continue;
    }
    if (message->has_error()) {
      result.error = "server error: " + message->error().message();
      break;
    }
    if (!message->has_frame() || Clock::now() < measureFrom) continue;
    const Clock::time_point arrived = Clock::now();
    if (lastFrame)
      result.longestGapMs =
          std::max(result.longestGapMs, std::chrono::duration<double, std::milli>(arrived - *lastFrame).count());
    lastFrame = arrived;
    const v1::Frame& frame = message->frame();
    ++result.frames;
    ++framesSoFar;
    result.bytes += frame.jpeg().size();
    result.skippedFrames = frame.skipped_frames();
    if (frame.input_sequence() > 0) result.latencyMs.push_back(steadyMilliseconds() - frame.client_time_ms());
    renderSum += frame.render_ms();
    encodeSum += frame.encode_ms();
    serverSum += frame.server_ms();
    // An estimate that found no mirror pixel in view claims nothing ([0, 1]): left out.
    if (frame.has_accuracy() && frame.accuracy().frame() != lastEstimated && frame.accuracy().sampled() > 0) {
      const v1::AccuracyEstimate& accuracy = frame.accuracy();
      lastEstimated = accuracy.frame();
      ++result.estimatedFrames;
      mismatchSum += accuracy.mismatch();
      accuracyMsSum += accuracy.trace_ms();
      result.worstMismatchHigh = std::max(result.worstMismatchHigh, accuracy.high());
    }
  }
  result.reconnects = client.reconnects();
  client.close();
  const double seconds = std::chrono::duration<double>(end - measureFrom).count();
  result.fps = static_cast<double>(result.frames) / seconds;
  if (result.frames > 0) {
    const double n = static_cast<double>(result.frames);
    result.renderMsMean = renderSum / n;
    result.encodeMsMean = encodeSum / n;
    result.serverMsMean = serverSum / n;
  }
  if (result.estimatedFrames > 0) {
    result.mismatchMean = mismatchSum / static_cast<double>(result.estimatedFrames);
    result.accuracyMsMean = accuracyMsSum / static_cast<double>(result.estimatedFrames);
  }
  return result;
}

}  // namespace

LoadReport runLoad(const LoadOptions& options) {
  LoadReport report;
  report.options = options;
  report.sessions.resize(static_cast<std::size_t>(std::max(0, options.sessions)));
  const Clock::time_point measureFrom = Clock::now() + options.warmup;
  const Clock::time_point end = measureFrom + options.duration;
  std::atomic<std::uint64_t> framesSoFar{0};
  std::vector<std::thread> threads;
  for (int i = 0; i < options.sessions; ++i)
    threads.emplace_back([&, i] {
      report.sessions[static_cast<std::size_t>(i)] = runSession(options, i, measureFrom, end, framesSoFar);
    });
  while (Clock::now() < end) {
    std::this_thread::sleep_for(std::min<Clock::duration>(std::chrono::seconds(1), end - Clock::now()));
    if (options.progress)
      options.progress(std::max(0.0, std::chrono::duration<double>(Clock::now() - measureFrom).count()),
                       framesSoFar.load());
  }
  for (std::thread& thread : threads) thread.join();

  report.seconds = std::chrono::duration<double>(options.duration).count();
  std::vector<double> latencies, fps;
  double renderSum = 0.0, encodeSum = 0.0, mismatchSum = 0.0, accuracyMsSum = 0.0;
  for (const SessionLoad& session : report.sessions) {
    const auto estimated = static_cast<double>(session.estimatedFrames);
    report.estimatedFrames += session.estimatedFrames;
    mismatchSum += session.mismatchMean * estimated;
    accuracyMsSum += session.accuracyMsMean * estimated;
    report.worstMismatchHigh = std::max(report.worstMismatchHigh, session.worstMismatchHigh);
    report.frames += session.frames;
    report.bytes += session.bytes;
    report.skippedFrames += session.skippedFrames;
    report.errors += session.error.empty() ? 0 : 1;
    latencies.insert(latencies.end(), session.latencyMs.begin(), session.latencyMs.end());
    fps.push_back(session.fps);
    renderSum += session.renderMsMean * static_cast<double>(session.frames);
    encodeSum += session.encodeMsMean * static_cast<double>(session.frames);
  }
  if (!fps.empty()) {
    report.fpsMean = std::accumulate(fps.begin(), fps.end(), 0.0) / static_cast<double>(fps.size());
    report.fpsMin = *std::min_element(fps.begin(), fps.end());
  }
  report.latencyP50 = nearestRankPercentile(latencies, 0.5);
  report.latencyP99 = nearestRankPercentile(latencies, 0.99);
  report.latencyMax = nearestRankPercentile(latencies, 1.0);
  if (report.frames > 0) {
    const double n = static_cast<double>(report.frames);
    report.renderMsMean = renderSum / n;
    report.encodeMsMean = encodeSum / n;
    report.bytesPerFrame = static_cast<double>(report.bytes) / n;
  }
  if (report.estimatedFrames > 0) {
    report.mismatchMean = mismatchSum / static_cast<double>(report.estimatedFrames);
    report.accuracyMsMean = accuracyMsSum / static_cast<double>(report.estimatedFrames);
  }
  return report;
}

std::string loadReportJson(const LoadReport& report) {
  nlohmann::json sessions = nlohmann::json::array();
  for (const SessionLoad& s : report.sessions)
    sessions.push_back({{"frames", s.frames},
                        {"fps", s.fps},
                        {"latency_ms_p50", nearestRankPercentile(s.latencyMs, 0.5)},
                        {"latency_ms_p99", nearestRankPercentile(s.latencyMs, 0.99)},
                        {"bytes", s.bytes},
                        {"skipped_frames", s.skippedFrames},
                        {"render_ms_mean", s.renderMsMean},
                        {"encode_ms_mean", s.encodeMsMean},
                        {"server_ms_mean", s.serverMsMean},
                        {"reconnects", s.reconnects},
                        {"resumes_refused", s.resumesRefused},
                        {"resumed", s.resumed},
                        {"longest_gap_ms", s.longestGapMs},
                        {"estimated_frames", s.estimatedFrames},
                        {"mirror_mismatch_mean", s.mismatchMean},
                        {"mirror_mismatch_worst_high", s.worstMismatchHigh},
                        {"accuracy_ms_mean", s.accuracyMsMean},
                        {"error", s.error}});
  const LoadOptions& o = report.options;
  nlohmann::json out = {{"options",
                         {{"host", o.address.host},
                          {"port", o.address.port},
                          {"encoding", o.encoding == protocol::Encoding::Proto ? "proto" : "json"},
                          {"sessions", o.sessions},
                          {"width", o.width},
                          {"height", o.height},
                          {"seconds", report.seconds},
                          {"input_hz", o.inputHz}}},
                        {"aggregate",
                         {{"frames", report.frames},
                          {"fps_per_session_mean", report.fpsMean},
                          {"fps_per_session_min", report.fpsMin},
                          {"latency_ms_p50", report.latencyP50},
                          {"latency_ms_p99", report.latencyP99},
                          {"latency_ms_max", report.latencyMax},
                          {"render_ms_mean", report.renderMsMean},
                          {"encode_ms_mean", report.encodeMsMean},
                          {"bytes_per_frame", report.bytesPerFrame},
                          {"bytes", report.bytes},
                          {"skipped_frames", report.skippedFrames},
                          {"estimated_frames", report.estimatedFrames},
                          {"mirror_mismatch_mean", report.mismatchMean},
                          {"mirror_mismatch_worst_high", report.worstMismatchHigh},
                          {"accuracy_ms_mean", report.accuracyMsMean},
                          {"errors", report.errors}}},
                        {"sessions", sessions}};
  return out.dump(2);
}

}  // namespace specula::client
