// `specula bench soak`: real sessions with misbehaving clients held for minutes against a real
// `specula serve` child process rendering on the GL renderer, watched from outside for growth.
#include <signal.h>
#include <stdlib.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>
#include <tuple>

#include "ConnectionOptions.h"
#include "LoadRun.h"
#include "app/BenchCommands.h"
#include "app/ChildProcess.h"
#include "app/GlSetup.h"
#include "app/OutputFiles.h"
#include "app/PrivateFolder.h"
#include "app/SceneSource.h"
#include "app/SoakReport.h"
#include "base/CommandLine.h"
#include "session/ResumeStore.h"

namespace specula::app {

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

CommandLine soakBenchOptions() {
  return CommandLine(
      "specula bench soak [options]",
      "Starts `specula serve` (this executable) on a free loopback port with a resume secret and holds --sessions\n"
      "WebSocket sessions against it for --minutes, each sending camera updates at 60 Hz and playing one role in\n"
      "turn: steady; a slow reader (250 ms before each read); a reader on a thin pipe (8 KiB receive buffer) that\n"
      "stops for 15 s every 30 s while its camera keeps moving, so the server skips its frames and drops it at\n"
      "the 5 s write deadline, and it resumes; a client that vanishes (socket closed, no close handshake) every 10 s "
      "and resumes;\n"
      "one that changes render settings every 3 s. Four times in the run every session drops at once and\n"
      "resumes (a reconnect storm). Every --sample-seconds it reads the server's resident memory and open file\n"
      "descriptors (/proc/<pid>) and its /metrics (live GL objects, sessions, frames sent and skipped, write\n"
      "timeouts, resumes).\n"
      "Prints the samples as a table, frames delivered and latency percentiles, and the trend of memory, file\n"
      "descriptors and GL objects after the warm-up (a least-squares line). Fails (exit 1) naming what grew\n"
      "beyond its tolerance with a slope 3 standard errors above zero, or when the server's counters disagree\n"
      "with what the clients saw (frames sent < frames received, resumes counted outside what the clients\n"
      "were told and tried, fewer write timeouts than stops the server ended, sessions left open after the\n"
      "clients closed), a session ended in an error or\n"
      "received no frame, or the server did not exit cleanly on SIGTERM.",
      {
          {"scene", "NAME|FILE", kSceneOptionHelp, "checker-sphere"},
          {"sessions", "N", "concurrent sessions", "16"},
          {"minutes", "M", "length of the run (fractions allowed: 0.5)", "10"},
          {"warmup", "S", "seconds left out of the growth trends", "a fifth of the run, at most 60"},
          {"sample-seconds", "S", "seconds between two samples of the server", "5"},
          {"size", "WxH", "frame size every session asks for", "640x360"},
          {"encoding", "proto|json", "WebSocket subprotocol the clients use", "proto"},
          {"render-threads", "N", "the server's render workers (GL contexts)", "1"},
          {"csv", "FILE", "CSV output, one row per sample", "soak.csv"},
          {"json", "FILE", "JSON output: samples, trends, checks and the clients' figures", "soak.json"},
          glOption(),
      });
}

constexpr CommandFailure failSoak{"specula bench soak"};

// The server's sessions once they are all gone (or `timeout` passed): the sample taken then.
Result<ServerSample> sampleWhenClosed(pid_t pid, std::uint16_t port, double seconds) {
  Result<ServerSample> sample = sampleServer(pid, port);
  for (const auto deadline = std::chrono::steady_clock::now() + 10s;
       sample && sample->sessions > 0.0 && std::chrono::steady_clock::now() < deadline;) {
    std::this_thread::sleep_for(200ms);
    sample = sampleServer(pid, port);
  }
  if (sample) sample->seconds = seconds;
  return sample;
}

}  // namespace

int runSoakBench(std::span<const std::string> arguments) {
  CommandLine options = soakBenchOptions();
  if (auto exitCode = options.parseOrExit(arguments, failSoak)) return *exitCode;
  auto sessions = options.integer("sessions", 1, 256);
  auto minutes = options.number("minutes");
  auto sampleSeconds = options.number("sample-seconds");
  auto size = options.size("size", kMaxBenchSide);
  auto renderThreads = options.integer("render-threads", 1, 64);
  auto encoding = client::parseEncoding(options.text("encoding"));
  if (!sessions) return failSoak(sessions.error());
  if (!minutes || *minutes <= 0.0 || *minutes > 24 * 60.0) return failSoak("--minutes expects a number in (0, 1440]");
  if (!sampleSeconds || *sampleSeconds < 1.0 || *sampleSeconds > 600.0)
    return failSoak("--sample-seconds expects a number in [1, 600]");
  if (!size) return failSoak(size.error());
  if (!renderThreads) return failSoak(renderThreads.error());
  if (!encoding) return failSoak(encoding.error());
  if (auto backend = parseGlOption(options.text("gl")); !backend) return failSoak(backend.error());
  const double runSeconds = *minutes * 60.0;
  double warmupSeconds = std::min(60.0, runSeconds / 5.0);
  if (options.has("warmup")) {
    auto warmup = options.number("warmup");
    if (!warmup || *warmup < 0.0 || *warmup >= runSeconds)
      return failSoak("--warmup expects seconds in [0, the run's " + std::to_string(static_cast<int>(runSeconds)) +
                      ")");
    warmupSeconds = *warmup;
  }
  for (const char* output : {"csv", "json"})
    if (Status status = checkWritable(options.text(output)); !status) return failSoak(status.error());

  auto folder = PrivateFolder::create("specula-soak-");
  if (!folder) return failSoak(folder.error());
  // 64 hex digits, this run only.
  const fs::path secretFile = folder->writeSecret("resume.secret", session::randomToken() + session::randomToken());

  std::error_code ignored;
  auto server = ChildProcess::start({fs::read_symlink("/proc/self/exe", ignored).string(), "serve", "--port", "0",
                                     "--public-metrics", "--resume-secret-file", secretFile.string(), "--scene",
                                     options.text("scene"), "--max-sessions", std::to_string(2 * *sessions),
                                     "--render-threads", std::to_string(*renderThreads), "--gl", options.text("gl")});
  if (!server) return failSoak(server.error());
  std::fprintf(stderr, "bench soak: starting specula serve ...\n");
  const auto listening = (*server)->waitFor(std::regex("listening on 127\\.0\\.0\\.1:(\\d+)"), 120s);
  if (!listening) return failSoak("specula serve did not start:\n" + (*server)->output());
  const auto port = static_cast<std::uint16_t>(std::stoi((*listening)[1]));
  const pid_t pid = (*server)->pid();

  SoakRun run;
  run.scene = options.text("scene");
  run.sessions = *sessions;
  std::tie(run.width, run.height) = *size;
  run.runSeconds = runSeconds;
  run.warmupSeconds = warmupSeconds;
  for (int i = 0; i < *sessions; ++i) run.roles.push_back(SoakClients::role(i));
  std::string samplingError;
  const auto takeSample = [&](double seconds, std::uint64_t frames) {
    auto sample = sampleServer(pid, port);
    if (!sample) return void(samplingError = sample.error());
    sample->seconds = seconds;
    sample->framesReceived = frames;
    run.samples.push_back(*sample);
    std::fprintf(stderr, "%s", soakTableRow(*sample).c_str());
  };
  std::fprintf(stderr, "bench soak: %d sessions for %.0f s, a sample every %.0f s\n%s", *sessions, runSeconds,
               *sampleSeconds, soakTableHeader().c_str());
  takeSample(0.0, 0);

  SoakClients clients(*sessions, SoakTiming{.runSeconds = runSeconds});
  client::LoadOptions load;
  load.address = {"127.0.0.1", port, ""};
  load.encoding = *encoding;
  load.sessions = *sessions;
  std::tie(load.width, load.height) = *size;
  load.duration = std::chrono::milliseconds(static_cast<long>(runSeconds * 1000.0));
  load.warmup = 0ms;  // every frame counts, so the clients' totals compare with the server's counters
  load.sessionReconnect = [&](int session) { return clients.connection(session, load.reconnect); };
  load.script = [&](int session, double seconds, client::ResumingClient& client) {
    return clients.act(session, seconds, client);
  };
  double nextSample = *sampleSeconds;
  load.progress = [&](double seconds, std::uint64_t frames) {
    if (seconds + 0.5 < nextSample) return;
    nextSample += *sampleSeconds;
    takeSample(seconds, frames);
  };
  run.load = client::runLoad(load);
  run.actions = clients.actions();
  for (const client::SessionLoad& session : run.load.sessions)
    if (!session.error.empty()) std::fprintf(stderr, "  session error: %s\n", session.error.c_str());

  if (auto closed = sampleWhenClosed(pid, port, runSeconds)) {
    closed->framesReceived = run.load.frames;
    run.afterClose = *closed;
  } else {
    samplingError = closed.error();
  }
  (*server)->signal(SIGTERM);
  run.serverExit = (*server)->waitExit(10s);

  SoakVerdict verdict = judgeSoak(run);
  if (!samplingError.empty()) {
    verdict.checks.push_back("FAIL - the server answered every sample: " + samplingError);
    verdict.failures.push_back("the server stopped answering");
  }
  std::string table = soakTableHeader();
  for (const ServerSample& sample : run.samples) table += soakTableRow(sample);
  std::cout << "bench soak: " << options.text("encoding") << " encoding, " << *renderThreads
            << " render thread(s); latency = camera update sent -> frame reflecting it received\n"
            << table << soakSummary(run, verdict);
  for (const char* option : {"csv", "json"})
    if (Status status =
            writeFile(options.text(option), option == std::string("csv") ? soakCsv(run) : soakJson(run, verdict));
        !status)
      return failSoak(status.error());
  std::cout << "wrote " << options.text("csv") << " and " << options.text("json") << "\n";
  if (verdict.failures.empty()) return 0;
  std::string failures;
  for (const std::string& failure : verdict.failures) failures += (failures.empty() ? "" : "; ") + failure;
  return failSoak(failures);
}

}  // namespace specula::app
