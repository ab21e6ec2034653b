#include "LoadRun.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/glm.hpp>
#include <mutex>
#include <nlohmann/json.hpp>
#include <numeric>
#include <thread>

namespace specula::client {

namespace {

using Clock = std::chrono::steady_clock;

struct Orbit {
  glm::vec3 target{0.0f}, up{0.0f, 1.0f, 0.0f};
  float radius = 5.0f, height = 1.0f, fov = 45.0f, phase = 0.0f;
};

v1::ClientMessage cameraOnOrbit(const Orbit& orbit, double degrees, std::uint64_t sequence) {
  const double radians = (orbit.phase + degrees) * 3.14159265358979 / 180.0;
  v1::ClientMessage message;
  v1::CameraUpdate& camera = *message.mutable_camera();
  camera.mutable_eye()->set_x(orbit.target.x + orbit.radius * static_cast<float>(std::sin(radians)));
  camera.mutable_eye()->set_y(orbit.target.y + orbit.height);
  camera.mutable_eye()->set_z(orbit.target.z + orbit.radius * static_cast<float>(std::cos(radians)));
  camera.mutable_target()->set_x(orbit.target.x);
  camera.mutable_target()->set_y(orbit.target.y);
  camera.mutable_target()->set_z(orbit.target.z);
  camera.mutable_up()->set_x(orbit.up.x);
  camera.mutable_up()->set_y(orbit.up.y);
  camera.mutable_up()->set_z(orbit.up.z);
  camera.set_fov_degrees(orbit.fov);
  camera.set_sequence(sequence);
  camera.set_client_time_ms(steadyMilliseconds());
  return message;
}

// The scene's default camera as an orbit around its target, phase-shifted per session.
Orbit orbitFrom(const v1::SceneInfo& scene, int session, int sessions) {
  Orbit orbit;
  const glm::vec3 eye(scene.eye().x(), scene.eye().y(), scene.eye().z());
  orbit.target = {scene.target().x(), scene.target().y(), scene.target().z()};
  orbit.up = {scene.up().x(), scene.up().y(), scene.up().z()};
  const glm::vec3 offset = eye - orbit.target;
  orbit.height = offset.y;
  orbit.radius = std::max(0.1f, std::hypot(offset.x, offset.z));
  orbit.fov = scene.fov_degrees() > 0.0f ? scene.fov_degrees() : 45.0f;
  orbit.phase = static_cast<float>(std::atan2(offset.x, offset.z) * 180.0 / 3.14159265358979) +
                360.0f * static_cast<float>(session) / static_cast<float>(std::max(1, sessions));
  return orbit;
}

SessionLoad runSession(const LoadOptions& options, int index, Clock::time_point measureFrom, Clock::time_point end,
                       std::atomic<std::uint64_t>& framesSoFar) {
  SessionLoad result;
  auto connected = SpeculaClient::connect(options.address, options.encoding);
  if (!connected) {
    result.error = connected.error();
    return result;
  }
  SpeculaClient& client = **connected;
  v1::ClientMessage hello;
  hello.mutable_hello()->set_protocol_version(1);
  hello.mutable_hello()->set_width(static_cast<std::uint32_t>(options.width));
  hello.mutable_hello()->set_height(static_cast<std::uint32_t>(options.height));
  if (Status sent = client.send(hello); !sent) {
    result.error = sent.error();
    return result;
  }
  std::optional<Orbit> orbit;
  const auto inputInterval = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / options.inputHz));
  Clock::time_point nextInput = Clock::now();
  const Clock::time_point start = Clock::now();
  std::uint64_t sequence = 0;
  double renderSum = 0.0, encodeSum = 0.0, serverSum = 0.0;
  while (Clock::now() < end) {
    if (orbit && Clock::now() >= nextInput) {
      const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
      if (Status sent = client.send(cameraOnOrbit(*orbit, seconds * options.orbitDegreesPerSecond, ++sequence)); !sent) {
        result.error = sent.error();
        break;
      }
      nextInput += inputInterval;
    }
    const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(
        std::min(end, orbit ? nextInput : end) - Clock::now());
    auto message = client.receive(std::max(std::chrono::milliseconds(1), wait));
    if (!message) {
      if (client.closeInfo()) {
        result.error = "server closed the session: " + std::to_string(client.closeInfo()->code) + " " +
                       client.closeInfo()->reason;
        break;
      }
      continue;  // timed out: time for the next input
    }
    if (message->has_welcome()) orbit = orbitFrom(message->welcome().scene(), index, options.sessions);
    if (message->has_error()) {
      result.error = "server error: " + message->error().message();
      break;
    }
    if (!message->has_frame() || Clock::now() < measureFrom) continue;
    const v1::Frame& frame = message->frame();
    ++result.frames;
    ++framesSoFar;
    result.bytes += frame.jpeg().size();
    result.skippedFrames = frame.skipped_frames();
    if (frame.input_sequence() > 0) result.latencyMs.push_back(steadyMilliseconds() - frame.client_time_ms());
    renderSum += frame.render_ms();
    encodeSum += frame.encode_ms();
    serverSum += frame.server_ms();
  }
  client.close();
  const double seconds = std::chrono::duration<double>(end - measureFrom).count();
  result.fps = static_cast<double>(result.frames) / seconds;
  if (result.frames > 0) {
    const double n = static_cast<double>(result.frames);
    result.renderMsMean = renderSum / n;
    result.encodeMsMean = encodeSum / n;
    result.serverMsMean = serverSum / n;
  }
  return result;
}

}  // namespace

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double rank = std::ceil(p / 100.0 * static_cast<double>(values.size()));
  const std::size_t index = static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(values.size()))) - 1;
  return values[index];
}

LoadReport runLoad(const LoadOptions& options) {
  LoadReport report;
  report.options = options;
  report.sessions.resize(static_cast<std::size_t>(std::max(0, options.sessions)));
  const Clock::time_point measureFrom = Clock::now() + options.warmup;
  const Clock::time_point end = measureFrom + options.duration;
  std::atomic<std::uint64_t> framesSoFar{0};
  std::vector<std::thread> threads;
  for (int i = 0; i < options.sessions; ++i)
    threads.emplace_back([&, i] { report.sessions[static_cast<std::size_t>(i)] = runSession(options, i, measureFrom, end, framesSoFar); });
  while (Clock::now() < end) {
    std::this_thread::sleep_for(std::min<Clock::duration>(std::chrono::seconds(1), end - Clock::now()));
    if (options.progress)
      options.progress(std::max(0.0, std::chrono::duration<double>(Clock::now() - measureFrom).count()), framesSoFar.load());
  }
  for (std::thread& thread : threads) thread.join();

  report.seconds = std::chrono::duration<double>(options.duration).count();
  std::vector<double> latencies, fps;
  double renderSum = 0.0, encodeSum = 0.0;
  for (const SessionLoad& session : report.sessions) {
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
  report.latencyP50 = percentile(latencies, 50);
  report.latencyP99 = percentile(latencies, 99);
  report.latencyMax = percentile(latencies, 100);
  if (report.frames > 0) {
    const double n = static_cast<double>(report.frames);
    report.renderMsMean = renderSum / n;
    report.encodeMsMean = encodeSum / n;
    report.bytesPerFrame = static_cast<double>(report.bytes) / n;
  }
  return report;
}

std::string loadReportJson(const LoadReport& report) {
  nlohmann::json sessions = nlohmann::json::array();
  for (const SessionLoad& s : report.sessions)
    sessions.push_back({{"frames", s.frames},
                        {"fps", s.fps},
                        {"latency_ms_p50", percentile(s.latencyMs, 50)},
                        {"latency_ms_p99", percentile(s.latencyMs, 99)},
                        {"bytes", s.bytes},
                        {"skipped_frames", s.skippedFrames},
                        {"render_ms_mean", s.renderMsMean},
                        {"encode_ms_mean", s.encodeMsMean},
                        {"server_ms_mean", s.serverMsMean},
                        {"error", s.error}});
  const LoadOptions& o = report.options;
  nlohmann::json out = {
      {"options",
       {{"host", o.address.host},
        {"port", o.address.port},
        {"encoding", o.encoding == net::Encoding::Proto ? "proto" : "json"},
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
        {"errors", report.errors}}},
      {"sessions", sessions}};
  return out.dump(2);
}

}  // namespace specula::client
