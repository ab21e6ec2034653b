// `specula bench serve`: the streaming service under load on loopback. An in-process server with the
// GL renderer, and 1, 4 and 16 client sessions at each size sending camera updates at 60 Hz.
#include <cstdio>
#include <filesystem>
#include <functional>
#include <utility>
#include <iostream>

#include "ConnectionOptions.h"
#include "LoadRun.h"
#include "base/CommandFailure.h"
#include "base/CommandLine.h"
#include "app/Commands.h"
#include "app/GlSetup.h"
#include "app/OutputFiles.h"
#include "app/SceneSource.h"
#include "app/LoopbackCluster.h"
#include "app/Service.h"
#include "session/ResumeStore.h"

namespace specula::app {

namespace {

CommandLine serveBenchOptions() {
  return CommandLine(
      "specula bench serve [options]",
      "Starts the streaming service in this process on a free loopback port and, for every (sessions, size),\n"
      "runs that many WebSocket clients, each orbiting the scene on its own camera path and sending camera\n"
      "updates at 60 Hz. Measures per session: frames per second, input-to-frame latency (a camera update\n"
      "sent → the first frame reflecting it received) p50/p99, render and encode time per frame, bytes per\n"
      "frame and frames skipped (latest wins). Checks p99 latency against two frame intervals.\n"
      "--instances N instead starts N `specula serve` processes sharing a resume secret behind HAProxy\n"
      "(docker/haproxy/specula.cfg; HAProxy must be installed) and runs the clients through its front: the\n"
      "table adds how the sessions spread over the instances, and a last run kills one instance a third of\n"
      "the way in and reports how many sessions reconnected and resumed and the longest gap in their frames.",
      withSceneChoice({
          {"scene", "NAME|FILE", kSceneOptionHelp, "checker-sphere"},
          {"sessions", "LIST", "comma-separated session counts", "1,4,16"},
          {"sizes", "LIST", "comma-separated frame sizes", "640x360,1280x720"},
          {"seconds", "S", "measured seconds per configuration", "5"},
          {"warmup", "S", "seconds per configuration before measuring", "1"},
          {"encoding", "proto|json", "WebSocket subprotocol the clients use", "proto"},
          {"render-threads", "N", "server render workers (GL contexts)", "1"},
          {"instances", "N", "serve processes behind HAProxy on loopback (0: one service in this process)", "0"},
          {"haproxy-config", "FILE", "with --instances: HAProxy's shared configuration", "docker/haproxy/specula.cfg"},
          {"csv", "FILE", "CSV output, one row per configuration", "serve.csv"},
          {"json", "FILE", "JSON output", "serve.json"},
          glOption(),
      }));
}

constexpr CommandFailure fail{"specula bench serve"};

std::string number(double value, int decimals) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

}  // namespace

int runServeBench(std::span<const std::string> arguments) {
  CommandLine options = serveBenchOptions();
  if (auto exitCode = options.parseOrExit(arguments, fail)) return *exitCode;
  auto seconds = options.number("seconds");
  auto warmup = options.number("warmup");
  auto renderThreads = options.integer("render-threads", 1, 64);
  if (!seconds || *seconds <= 0.0 || *seconds > 3600.0) return fail("--seconds expects a number in (0, 3600]");
  if (!warmup || *warmup < 0.0 || *warmup > 600.0) return fail("--warmup expects a number in [0, 600]");
  if (!renderThreads) return fail(renderThreads.error());
  auto encoding = client::parseEncoding(options.text("encoding"));
  if (!encoding) return fail(encoding.error());
  if (auto backend = parseGlOption(options.text("gl")); !backend) return fail(backend.error());
  auto sessionCounts = options.integerList("sessions", 1, 256);
  auto sizes = options.sizeList("sizes", 4096);
  if (!sessionCounts) return fail(sessionCounts.error());
  if (!sizes) return fail(sizes.error());
  for (const char* output : {"csv", "json"})
    if (Status status = checkWritable(options.text(output)); !status) return fail(status.error());
  auto sceneChoice = parseSceneChoice(options);
  if (!sceneChoice) return fail(sceneChoice.error());
  auto scene = loadScene(options.text("scene"), *sceneChoice);
  if (!scene) return fail(scene.error());

  auto instances = options.integer("instances", 0, 16);
  if (!instances) return fail(instances.error());
  int maxSessions = 0;
  for (int count : *sessionCounts) maxSessions = std::max(maxSessions, count);

  // One service in this process, or N processes behind HAProxy: the clients only see a port.
  std::unique_ptr<Service> service;
  std::unique_ptr<LoopbackCluster> cluster;
  std::uint16_t port = 0;
  if (*instances == 0) {
    ServiceConfig config;
    config.scene = *scene;
    config.glBackend = options.text("gl");
    config.hub.maxSessions = maxSessions;
    config.hub.scheduler.renderThreads = *renderThreads;
    config.server.port = 0;
    auto started = Service::start(std::move(config));
    if (!started) return fail(started.error());
    service = std::move(*started);
    port = service->port();
  } else {
    LoopbackClusterOptions clusterOptions;
    std::error_code ignored;
    clusterOptions.specula = std::filesystem::read_symlink("/proc/self/exe", ignored).string();
    clusterOptions.instances = *instances;
    clusterOptions.resumeSecret = session::randomToken() + session::randomToken();  // 64 hex digits, this run only
    clusterOptions.drainSeconds = 0;
    clusterOptions.haproxyConfig = options.text("haproxy-config");
    clusterOptions.serveArguments = {
        "--scene",          options.text("scene"),          "--max-sessions", std::to_string(maxSessions + 4),
        "--render-threads", std::to_string(*renderThreads), "--gl",           options.text("gl")};
    for (const OptionSpec& spec : sceneChoiceOptions())  // each instance takes the scene as given here
      if (options.has(spec.name))
        clusterOptions.serveArguments.insert(clusterOptions.serveArguments.end(),
                                             {"--" + std::string(spec.name), options.text(spec.name)});
    std::fprintf(stderr, "bench serve: starting %d instances and HAProxy ...\n", *instances);
    auto started = LoopbackCluster::start(clusterOptions);
    if (!started) return fail(started.error());
    cluster = std::move(*started);
    port = cluster->frontPort();
  }
  // Open sessions per instance now, "4/4/4".
  const auto spread = [&] {
    std::string text;
    for (std::size_t i = 0; i < cluster->instances(); ++i) {
      const std::optional<int> open = cluster->sessions(i);
      text += (i ? "/" : "") + (open ? std::to_string(*open) : std::string("-"));
    }
    return text;
  };

  std::string csv =
      "scene,sessions,width,height,seconds,fps_per_session_mean,fps_per_session_min,latency_ms_p50,"
      "latency_ms_p99,two_frame_intervals_ms,render_ms_mean,encode_ms_mean,bytes_per_frame,"
      "skipped_frames,errors,estimated_frames,mirror_mismatch_estimate_mean,accuracy_ms_mean,instances,"
      "sessions_per_instance\n";
  std::string json =
      "{\"scene\": \"" + (*scene)->name + "\", \"instances\": " + std::to_string(*instances) + ", \"runs\": [\n";
  std::string table =
      "sessions  size       fps/session (min)  latency p50   p99 ms  2 intervals  render ms  encode ms  KB/frame  "
      "skipped  errors  estimated  mismatch est.  estimate ms" +
      std::string(cluster ? "  sessions per instance" : "") + "\n";
  const std::size_t total = sessionCounts->size() * sizes->size() + (cluster ? 1 : 0);
  std::size_t done = 0;
  // Runs one configuration; each event is called once, when its share of the measured time has passed.
  using Events = std::vector<std::pair<double, std::function<void()>>>;
  const auto run = [&](int sessions, int width, int height, Events events) {
    client::LoadOptions load;
    load.address = {"127.0.0.1", port, ""};
    load.encoding = *encoding;
    load.sessions = sessions;
    load.width = width;
    load.height = height;
    load.duration = std::chrono::milliseconds(static_cast<long>(*seconds * 1000.0));
    load.warmup = std::chrono::milliseconds(static_cast<long>(*warmup * 1000.0));
    const std::string label = std::to_string(sessions) + " x " + std::to_string(width) + "x" + std::to_string(height);
    ++done;
    load.progress = [&](double elapsed, std::uint64_t frames) {
      std::fprintf(stderr, "\rbench serve [%zu/%zu] %s: %.0f/%.0f s, %llu frames   ", done, total, label.c_str(),
                   elapsed, *seconds, static_cast<unsigned long long>(frames));
      for (auto& [at, event] : events)
        if (event && elapsed >= at * *seconds) std::exchange(event, nullptr)();
    };
    client::LoadReport report = client::runLoad(load);
    std::fprintf(stderr, "\n");
    for (const client::SessionLoad& session : report.sessions)
      if (!session.error.empty()) std::fprintf(stderr, "  session error: %s\n", session.error.c_str());
    return report;
  };
  for (const auto& [width, height] : *sizes) {
    for (int sessions : *sessionCounts) {
      std::string perInstance;
      const client::LoadReport report =
          run(sessions, width, height, cluster ? Events{{0.5, [&] { perInstance = spread(); }}} : Events{});
      const double twoIntervals = report.fpsMean > 0.0 ? 2000.0 / report.fpsMean : 0.0;
      // Frames whose live accuracy estimate arrived: the sampler takes the newest frame of a session when free.
      const double estimatedShare =
          report.frames ? 100.0 * static_cast<double>(report.estimatedFrames) / static_cast<double>(report.frames)
                        : 0.0;
      char row[512];
      std::snprintf(
          row, sizeof row,
          "%8d  %4dx%-4d  %8.1f (%5.1f)     %8.1f  %8.1f  %11.1f  %9.1f  %9.2f  %8.1f  %7llu  %6llu  %8.0f%%  "
          "%11.2f %%  %11.2f  %s\n",
          sessions, width, height, report.fpsMean, report.fpsMin, report.latencyP50, report.latencyP99, twoIntervals,
          report.renderMsMean, report.encodeMsMean, report.bytesPerFrame / 1024.0,
          static_cast<unsigned long long>(report.skippedFrames), static_cast<unsigned long long>(report.errors),
          estimatedShare, 100.0 * report.mismatchMean, report.accuracyMsMean, perInstance.c_str());
      table += row;
      csv += (*scene)->name + "," + std::to_string(sessions) + "," + std::to_string(width) + "," +
             std::to_string(height) + "," + number(report.seconds, 1) + "," + number(report.fpsMean, 2) + "," +
             number(report.fpsMin, 2) + "," + number(report.latencyP50, 2) + "," + number(report.latencyP99, 2) + "," +
             number(twoIntervals, 2) + "," + number(report.renderMsMean, 2) + "," + number(report.encodeMsMean, 2) +
             "," + number(report.bytesPerFrame, 0) + "," + std::to_string(report.skippedFrames) + "," +
             std::to_string(report.errors) + "," + std::to_string(report.estimatedFrames) + "," +
             number(report.mismatchMean, 4) + "," + number(report.accuracyMsMean, 2) + "," +
             std::to_string(*instances) + "," + perInstance + "\n";
      json += std::string(done > 1 ? ",\n" : "") + client::loadReportJson(report);
    }
  }
  std::string failover;
  if (cluster) {
    // The last run loses instance 0 a third of the way in: its sessions reconnect through the front.
    const auto [width, height] = sizes->front();
    std::string before, after;
    const client::LoadReport report = run(maxSessions, width, height,
                                          {{1.0 / 3.0,
                                            [&] {
                                              before = spread();
                                              cluster->kill(0);
                                            }},
                                           {0.9, [&] { after = spread(); }}});
    int moved = 0, refused = 0;
    double longestGap = 0.0;
    for (const client::SessionLoad& session : report.sessions) {
      if (session.reconnects == 0) continue;
      ++moved;
      refused += session.resumesRefused;
      longestGap = std::max(longestGap, session.longestGapMs);
    }
    char line[512];
    std::snprintf(
        line, sizeof line,
        "instance 0 killed a third of the way into %d sessions at %dx%d (sessions per instance %s, then %s): %d "
        "reconnected, %d resumed, longest gap between two frames %.0f ms; %.1f fps a session over the run, "
        "%llu errors\n",
        maxSessions, width, height, before.c_str(), after.c_str(), moved, moved - refused, longestGap, report.fpsMean,
        static_cast<unsigned long long>(report.errors));
    failover = line;
    json += std::string(done > 1 ? ",\n" : "") + client::loadReportJson(report);
  }
  json += "\n]}\n";
  if (service) service->stop();
  cluster.reset();
  std::cout << "scene " << (*scene)->name << ", " << options.text("encoding") << " encoding, " << *renderThreads
            << " render thread(s)"
            << (*instances ? ", " + std::to_string(*instances) + " instances behind HAProxy" : std::string())
            << "; latency = camera update sent -> frame reflecting it received\n"
            << table << failover;
  for (const char* option : {"csv", "json"})
    if (Status status = writeFile(options.text(option), option == std::string("csv") ? csv : json); !status)
      return fail(status.error());
  std::cout << "wrote " << options.text("csv") << " and " << options.text("json") << "\n";
  return 0;
}

}  // namespace specula::app
