// specula-load: N concurrent sessions against a server for a bounded time; per-session and aggregate
// fps, latency percentiles, skipped frames, errors and bytes; JSON for automation.
#include <cstdio>
#include <fstream>
#include <iostream>

#include "ConnectionOptions.h"
#include "LoadRun.h"
#include "base/CommandFailure.h"
#include "base/CommandLine.h"
#include "base/Percentile.h"

namespace {

constexpr specula::CommandFailure fail{"specula-load"};

}  // namespace

int main(int argc, char** argv) {
  using namespace specula;
  std::vector<OptionSpec> specs = client::connectionOptions();
  for (OptionSpec spec : std::initializer_list<OptionSpec>{
           {"sessions", "N", "concurrent sessions", "4"},
           {"seconds", "S", "measured seconds", "10"},
           {"warmup", "S", "seconds before measuring", "1"},
           {"size", "WxH", "viewport of every session", "640x360"},
           {"input-hz", "HZ", "camera updates per second per session", "60"},
           {"json", "FILE|-", "also write the report as JSON (- for stdout)", ""},
       })
    specs.push_back(spec);
  CommandLine options(
      "specula-load [options]",
      "Opens N sessions at once, each orbiting the scene on its own camera path and sending camera updates at\n"
      "--input-hz, for --seconds after a --warmup. Prints per-session and aggregate frames per second,\n"
      "input-to-frame latency percentiles (update sent → frame reflecting it received), skipped frames,\n"
      "errors and bytes; --json writes the same for automation. Exits 1 if any session failed.",
      std::move(specs));
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  if (auto exitCode = options.parseOrExit(arguments, fail)) return *exitCode;
  auto connection = client::parseConnectionOptions(options);
  auto sessions = options.integer("sessions", 1, 1024);
  auto seconds = options.number("seconds");
  auto warmup = options.number("warmup");
  auto size = options.size("size", 8192);
  auto inputHz = options.number("input-hz");
  if (!connection) return fail(connection.error());
  if (!sessions) return fail(sessions.error());
  if (!seconds || *seconds <= 0.0 || *seconds > 86400.0) return fail("--seconds expects a number in (0, 86400]");
  if (!warmup || *warmup < 0.0 || *warmup > 3600.0) return fail("--warmup expects a number in [0, 3600]");
  if (!size) return fail(size.error());
  if (!inputHz || *inputHz <= 0.0 || *inputHz > 1000.0) return fail("--input-hz expects a number in (0, 1000]");

  // Fail fast and clearly when nobody is there, before starting N threads.
  if (auto probe = client::SpeculaClient::connect(connection->address, connection->encoding); !probe)
    return fail(probe.error());

  client::LoadOptions load;
  load.address = connection->address;
  load.encoding = connection->encoding;
  load.sessions = *sessions;
  std::tie(load.width, load.height) = *size;
  load.duration = std::chrono::milliseconds(static_cast<long>(*seconds * 1000.0));
  load.warmup = std::chrono::milliseconds(static_cast<long>(*warmup * 1000.0));
  load.inputHz = *inputHz;
  load.reconnect = connection->reconnect;
  load.progress = [&](double elapsed, std::uint64_t frames) {
    std::fprintf(stderr, "\rspecula-load: %.0f/%.0f s, %llu frames from %d sessions   ", elapsed, *seconds,
                 static_cast<unsigned long long>(frames), *sessions);
  };
  const client::LoadReport report = client::runLoad(load);
  std::fprintf(stderr, "\n");

  std::printf("%d sessions, %dx%d, %s, %.0f s measured (after %.0f s warm-up)\n", *sessions, load.width, load.height,
              options.text("encoding").c_str(), *seconds, *warmup);
  std::printf(
      "session   fps  latency p50  p99 ms  render ms  encode ms  KB/frame  skipped  reconnects  longest gap ms  "
      "error\n");
  for (std::size_t i = 0; i < report.sessions.size(); ++i) {
    const client::SessionLoad& s = report.sessions[i];
    std::printf("%7zu  %5.1f  %11.1f  %6.1f  %9.1f  %9.2f  %8.1f  %7llu  %10d  %14.0f  %s\n", i + 1, s.fps,
                nearestRankPercentile(s.latencyMs, 0.5), nearestRankPercentile(s.latencyMs, 0.99), s.renderMsMean,
                s.encodeMsMean, s.frames ? static_cast<double>(s.bytes) / static_cast<double>(s.frames) / 1024.0 : 0.0,
                static_cast<unsigned long long>(s.skippedFrames), s.reconnects, s.longestGapMs,
                s.error.empty() ? "-" : s.error.c_str());
  }
  std::printf(
      "all      fps/session %.1f (min %.1f), latency p50 %.1f ms, p99 %.1f ms, max %.1f ms; %llu frames, "
      "%.1f KB/frame, %llu skipped, %llu errors\n",
      report.fpsMean, report.fpsMin, report.latencyP50, report.latencyP99, report.latencyMax,
      static_cast<unsigned long long>(report.frames), report.bytesPerFrame / 1024.0,
      static_cast<unsigned long long>(report.skippedFrames), static_cast<unsigned long long>(report.errors));
  if (report.estimatedFrames > 0)
    std::printf(
        "accuracy  %llu frames estimated live: mirror mismatch mean %.2f %%, the worst frame's 95 %% upper "
        "bound %.2f %%; %.1f ms server CPU a frame estimated\n",
        static_cast<unsigned long long>(report.estimatedFrames), 100.0 * report.mismatchMean,
        100.0 * report.worstMismatchHigh, report.accuracyMsMean);
  else std::printf("accuracy  no frame carried a live estimate (the sessions' accuracy_samples is 0)\n");
  if (options.has("json")) {
    const std::string json = client::loadReportJson(report) + "\n";
    if (options.text("json") == "-") {
      std::cout << json;
    } else {
      std::ofstream file(options.text("json"), std::ios::trunc);
      file << json;
      if (!file) return fail("could not write '" + options.text("json") + "': check the folder exists and is writable");
    }
  }
  return report.errors == 0 ? 0 : 1;
}
