// specula-path: plays a camera (and scene time) path against a server, at the path's own pace or as
// fast as frames come; writes a CSV row per frame and optionally every frame's JPEG; prints a summary.
// Exits 1 on protocol errors (an error message, a close, a frame that never comes).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <thread>

#include "CameraConversions.h"
#include "CameraPath.h"
#include "ConnectionOptions.h"
#include "ResumingClient.h"
#include "base/CommandFailure.h"
#include "base/CommandLine.h"
#include "base/Percentile.h"

namespace {

using namespace specula;
using Clock = std::chrono::steady_clock;

constexpr CommandFailure fail{"specula-path"};

v1::ClientMessage cameraMessage(const client::PathKey& key, std::uint64_t sequence) {
  v1::ClientMessage message;
  v1::CameraUpdate& camera = *message.mutable_camera() =
      protocol::cameraUpdate(key.eye, key.target, key.up, key.fovDegrees);
  camera.set_sequence(sequence);
  camera.set_client_time_ms(client::steadyMilliseconds());
  return message;
}

v1::ClientMessage animationMessage(v1::AnimationControl::Action action, double timeMs) {
  v1::ClientMessage message;
  message.mutable_animation()->set_action(action);
  message.mutable_animation()->set_time_ms(timeMs);
  return message;
}

// The live accuracy estimate's columns, empty until the server has sent one (or with it off), and the
// setting an accuracy target chose.
std::string accuracyCells(const v1::Frame& frame) {
  const std::string setting = frame.has_accuracy_control() ? frame.accuracy_control().setting() : "";
  if (!frame.has_accuracy()) return ",,,,,,," + setting;
  const v1::AccuracyEstimate& a = frame.accuracy();
  char cells[160];
  std::snprintf(cells, sizeof cells, "%llu,%u,%.5f,%.5f,%.5f,%.5f,%.5f,", static_cast<unsigned long long>(a.frame()),
                a.sampled(), a.mismatch(), a.low(), a.high(), a.window_mismatch(), a.window_high());
  return cells + setting;
}

std::string csvRow(std::size_t sample, double pathTime, const v1::Frame& frame, double latencyMs) {
  std::string stages;
  for (const v1::StageTime& stage : frame.stages())
    stages += (stages.empty() ? "" : ";") + stage.name() + "=" + std::to_string(stage.ms());
  char row[960];
  std::snprintf(
      row, sizeof row, "%zu,%.4f,%llu,%llu,%.3f,%.3f,%.3f,%.3f,%zu,%d,%u,%u,%.3f,%u,%u,%.3f,%u,%u,%u,%u,%s,%s\n",
      sample, pathTime, static_cast<unsigned long long>(frame.input_sequence()),
      static_cast<unsigned long long>(frame.number()), latencyMs, frame.render_ms(), frame.encode_ms(),
      frame.server_ms(), frame.jpeg().size(), frame.still() ? 1 : 0, frame.width(), frame.height(),
      frame.scene_time_ms(), frame.search().mirrors(), frame.search().searched(), frame.search().mean_steps(),
      frame.search().unsolved(), frame.tessellation().input_triangles(), frame.tessellation().finished_triangles(),
      frame.tessellation().midpoint_searches(), accuracyCells(frame).c_str(), stages.c_str());
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<OptionSpec> specs = {
      {"path", "FILE", "camera path, .json or .csv (see client/tools/CameraPath.h for the format)", ""}};
  for (OptionSpec& spec : client::connectionOptions()) specs.push_back(std::move(spec));
  for (OptionSpec spec : std::initializer_list<OptionSpec>{
           {"pace", "frames|realtime", "wait for each sample's frame, or follow the path's clock", "frames"},
           {"fps", "N", "samples per path second", "30"},
           {"size", "WxH", "viewport", "640x360"},
           {"csv", "FILE", "per-frame CSV", "path.csv"},
           {"frames-dir", "DIR", "write frame_00001.jpg ... here", ""},
           {"timeout", "S", "longest wait for one frame before giving up", "30"},
       })
    specs.push_back(spec);
  CommandLine options(
      "specula-path --path FILE.json|FILE.csv [options]",
      "Samples a keyframed camera path (linear between keys; optional scene_time seeks the paused animation)\n"
      "--fps times per path second and plays it against a server. --pace frames sends the next sample once the\n"
      "frame for the previous one arrived (every sample gets its frame); --pace realtime sends samples on the\n"
      "path's clock and records whatever frames come (latest wins). Writes one CSV row per frame: latency,\n"
      "server timings, search and tessellation statistics and the live accuracy estimate (the share of mirror\n"
      "pixels the server's ray tracer finds wrong in a sample, with its 95 % interval); --frames-dir also keeps\n"
      "every JPEG.",
      std::move(specs));
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  if (auto exitCode = options.parseOrExit(arguments, fail)) return *exitCode;
  if (!options.has("path")) return fail("--path FILE is required (a .json or .csv camera path)");
  auto path = client::loadCameraPath(options.text("path"));
  auto connection = client::parseConnectionOptions(options);
  auto fps = options.number("fps");
  auto size = options.size("size", 8192);
  auto timeout = options.number("timeout");
  const std::string pace = options.text("pace");
  if (!path) return fail(path.error());
  if (!connection) return fail(connection.error());
  if (!fps || *fps <= 0.0 || *fps > 1000.0) return fail("--fps expects a number in (0, 1000]");
  if (!size) return fail(size.error());
  if (!timeout || *timeout <= 0.0) return fail("--timeout expects a positive number of seconds");
  if (pace != "frames" && pace != "realtime") return fail("--pace expects frames or realtime, got '" + pace + "'");
  const std::string framesDir = options.text("frames-dir");
  if (!framesDir.empty()) {
    std::error_code error;
    std::filesystem::create_directories(framesDir, error);
    if (error) return fail("cannot create --frames-dir '" + framesDir + "': " + error.message());
  }
  std::ofstream csv(options.text("csv"), std::ios::trunc);
  if (!csv) return fail("could not write '" + options.text("csv") + "': check the folder exists and is writable");
  csv << "sample,path_time_s,input_sequence,frame,latency_ms,render_ms,encode_ms,server_ms,bytes,still,width,height,"
         "scene_time_ms,mirrors,searched,mean_steps,unsolved,tess_input,tess_finished,midpoint_searches,"
         "accuracy_frame,accuracy_sampled,accuracy_mismatch,accuracy_low,accuracy_high,window_mismatch,window_high,"
         "accuracy_setting,"
         "stages\n";

  v1::Hello hello;
  hello.set_protocol_version(1);
  hello.set_width(static_cast<std::uint32_t>(size->first));
  hello.set_height(static_cast<std::uint32_t>(size->second));
  // A lost connection is retried and the session resumed; the user is told on stderr.
  auto connected = client::ResumingClient::connect(
      connection->address, connection->encoding, hello, connection->reconnect,
      [](const std::string& notice) { std::fprintf(stderr, "\nspecula-path: %s\n", notice.c_str()); });
  if (!connected) return fail(connected.error());
  client::ResumingClient& client = **connected;
  const bool seeks = path->keys.front().sceneTime.has_value();

  const auto frameTimeout = std::chrono::milliseconds(static_cast<long>(*timeout * 1000.0));
  std::string problem;
  // Reads one message; frames are recorded; anything wrong ends the run with `problem` set.
  std::size_t frames = 0, currentSample = 0;
  double currentPathTime = 0.0;
  std::uint64_t bytes = 0;
  std::vector<double> latencies;
  std::map<std::uint64_t, double> sentAt;
  std::optional<v1::AccuracyEstimate> lastAccuracy;
  double worstFrameHigh = 0.0;
  auto receiveOne = [&](std::chrono::milliseconds wait) -> std::optional<v1::ServerMessage> {
    auto message = client.receive(wait);
    if (!message) {
      if (client.closeInfo())
        problem = "the server closed the connection: " + std::to_string(client.closeInfo()->code) + " " +
                  client.closeInfo()->reason;
      else if (message.error().find("timed out") == std::string::npos) problem = message.error();
      return std::nullopt;
    }
    if (message->has_error() && message->error().code() == v1::Error::RESUME_REFUSED) {
      std::fprintf(stderr, "\nspecula-path: %s\n",
                   message->error().message().c_str());  // the path sets camera and time anyway
    } else if (message->has_error()) {
      problem = "server error " + v1::Error::Code_Name(message->error().code()) + ": " + message->error().message();
      return std::nullopt;
    }
    // A reconnect that could not resume starts playing again; the path holds the clock itself.
    if (message->has_welcome() && client.reconnects() > 0 && !message->welcome().resumed() && seeks)
      (void)client.send(animationMessage(v1::AnimationControl::PAUSE, 0.0));
    if (message->has_frame()) {
      const v1::Frame& frame = message->frame();
      auto sent = sentAt.find(frame.input_sequence());
      const double latency = sent == sentAt.end() ? 0.0 : client::steadyMilliseconds() - sent->second;
      if (sent != sentAt.end()) latencies.push_back(latency);
      ++frames;
      bytes += frame.jpeg().size();
      csv << csvRow(currentSample, currentPathTime, frame, latency);
      if (frame.has_accuracy()) {
        lastAccuracy = frame.accuracy();
        // A frame with no mirror pixel sampled claims nothing ([0, 1]).
        if (frame.accuracy().sampled() > 0) worstFrameHigh = std::max(worstFrameHigh, frame.accuracy().high());
      }
      if (!framesDir.empty()) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05zu.jpg", frames);
        std::ofstream(std::filesystem::path(framesDir) / name, std::ios::binary) << frame.jpeg();
      }
    }
    return std::move(*message);
  };

  // The welcome first.
  while (problem.empty()) {
    auto message = receiveOne(frameTimeout);
    if (!message && problem.empty()) problem = "no welcome from the server within --timeout";
    if (message && message->has_welcome()) break;
  }
  if (problem.empty() && seeks) (void)client.send(animationMessage(v1::AnimationControl::PAUSE, 0.0));

  const std::size_t samples = static_cast<std::size_t>(std::floor(path->duration() * *fps)) + 1;
  const Clock::time_point start = Clock::now();
  std::uint64_t sequence = 0;
  for (std::size_t sample = 0; sample < samples && problem.empty(); ++sample) {
    currentSample = sample;
    currentPathTime = path->keys.front().time + static_cast<double>(sample) / *fps;
    const client::PathKey key = path->at(currentPathTime);
    if (pace == "realtime") {  // keep reading until this sample is due
      const auto due = start + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double>(currentPathTime - path->keys.front().time));
      while (problem.empty() && Clock::now() < due)
        receiveOne(std::max(std::chrono::milliseconds(1),
                            std::chrono::duration_cast<std::chrono::milliseconds>(due - Clock::now())));
    }
    if (key.sceneTime) (void)client.send(animationMessage(v1::AnimationControl::SEEK, *key.sceneTime * 1000.0));
    sentAt[++sequence] = client::steadyMilliseconds();
    if (Status sent = client.send(cameraMessage(key, sequence)); !sent) problem = sent.error();
    if (pace == "frames") {
      bool answered = false;
      const auto deadline = Clock::now() + frameTimeout;
      while (problem.empty() && !answered && Clock::now() < deadline) {
        auto message = receiveOne(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()));
        answered = message && message->has_frame() && message->frame().input_sequence() >= sequence;
      }
      if (problem.empty() && !answered) problem = "no frame for sample " + std::to_string(sample) + " within --timeout";
    }
    std::fprintf(stderr, "\rspecula-path: sample %zu/%zu, %zu frames   ", sample + 1, samples, frames);
  }
  std::fprintf(stderr, "\n");
  client.close();
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::printf(
      "%zu samples, %zu frames in %.2f s (%.1f fps); latency p50 %.1f ms, p99 %.1f ms; %.1f KB/frame; wrote %s\n",
      samples, frames, seconds, static_cast<double>(frames) / seconds, nearestRankPercentile(latencies, 0.5),
      nearestRankPercentile(latencies, 0.99),
      frames ? static_cast<double>(bytes) / static_cast<double>(frames) / 1024.0 : 0.0, options.text("csv").c_str());
  if (lastAccuracy)
    std::printf(
        "mirror mismatch, live estimate: last %u frames %.2f %% (95 %% interval %.2f to %.2f %%); the worst "
        "frame's upper bound %.2f %%\n",
        lastAccuracy->window_frames(), 100.0 * lastAccuracy->window_mismatch(), 100.0 * lastAccuracy->window_low(),
        100.0 * lastAccuracy->window_high(), 100.0 * worstFrameHigh);
  else
    std::printf(
        "mirror mismatch, live estimate: none received (the session's accuracy_samples is 0, or no frame "
        "was estimated yet)\n");
  if (!problem.empty()) return fail(problem);
  return 0;
}
