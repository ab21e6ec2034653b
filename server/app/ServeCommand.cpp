// `specula serve`: the streaming service. HTTP and WebSocket on one port; sessions rendered by GL
// workers and sent as JPEG frames; SIGTERM or SIGINT closes every client with 1001 within a second.
#include <pthread.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>

#include "base/CommandFailure.h"
#include "base/CommandLine.h"
#include "app/Commands.h"
#include "app/GlSetup.h"
#include "app/SceneSource.h"
#include "app/ReflectionOptions.h"
#include "app/Service.h"
#include "scene/AssetFiles.h"
#include "session/SessionSettingsSchema.h"
#include "session/SignedResume.h"

namespace specula::app {

namespace {

constexpr auto kShutdownGrace =
    std::chrono::milliseconds(900);  // every client closed within 1 s of SIGTERM (after the drain)
constexpr std::size_t kMaxSecretFileBytes = 4096;

CommandLine serveOptions() {
  std::vector<OptionSpec> specs = {
      {"bind", "ADDRESS", "address to listen on; anything but loopback needs --token", "127.0.0.1"},
      {"port", "PORT", "TCP port; 0 picks a free one (printed at start)", "8080"},
      {"scene", "NAME|FILE", kSceneOptionHelp, "checker-sphere"},
      {"max-sessions", "N", "concurrent sessions; more are refused with close code 1013", "16"},
      {"token", "SECRET", "clients must send it (?token= or Authorization: Bearer); also read from SPECULA_TOKEN", ""},
      {"web-root", "DIR", "folder served at / (the browser client)", SPECULA_DEFAULT_WEB_ROOT},
      {"render-threads", "N", "render workers, each with its own GL context", "1"},
      {"encode-threads", "N", "JPEG encoder threads", "1"},
      {"max-fps", "FPS", "frames per second per session at most", "60"},
      {"still-delay", "MS", "quiet time after input before a full-quality still frame", "150"},
      {"max-size", "WxH", "largest viewport a client may ask for", "3840x2160"},
      {"resume-secret-file", "FILE",
       "sign resume tokens with this secret (>= 32 bytes; also SPECULA_RESUME_SECRET): instances sharing it resume "
       "each other's sessions",
       "tokens kept in this process"},
      {"resume-lifetime", "SECONDS", "how long a resume token stays valid", "600"},
      {"drain-seconds", "N",
       "on SIGTERM: answer /readyz 503 and refuse new sessions for N s, then close every session (1001) and exit", "0"},
      {"public-metrics", "", "serve /metrics without the token (for a scraper inside a private network)", ""},
  };
  specs = withSceneChoice(std::move(specs));
  for (OptionSpec& spec :
       settingOptions(session::sessionSettingsSchema(), session::SessionSettings{}, {}, " (sessions' default)"))
    specs.push_back(std::move(spec));
  specs.push_back(glOption());
  return CommandLine(
      "specula serve [options]",
      "Serves a scene to browsers and thin clients on one port:\n"
      "  GET /         the browser client (files of --web-root)\n"
      "  GET /healthz  'ok' while the server runs (never needs the token)\n"
      "  GET /metrics  Prometheus text: sessions, frames sent and skipped, bytes, render/encode/latency histograms\n"
      "  /ws           WebSocket, subprotocol specula.v1.json (proto3 JSON text) or specula.v1.proto (binary);\n"
      "                messages are defined in proto/specula.proto\n"
      "  GET /readyz   'ready', or 503 'full' / 'draining': whether a balancer should send new sessions here\n"
      "  GET /settings-schema.json  every session setting: range or choices, default, protocol field\n"
      "Each session has its own camera, animation clock and settings and is rendered only when something\n"
      "changed. SIGTERM or SIGINT closes every client with code 1001 and exits (after --drain-seconds).",
      std::move(specs));
}

constexpr CommandFailure fail{"specula serve"};

// --resume-secret-file, else SPECULA_RESUME_SECRET, without a trailing newline; empty: neither given.
Result<std::string> readResumeSecret(const CommandLine& options) {
  std::string secret;
  if (options.has("resume-secret-file")) {
    auto bytes = scene::readBoundedFile(options.text("resume-secret-file"), kMaxSecretFileBytes);
    if (!bytes) return Error{"--resume-secret-file: " + bytes.error()};
    secret = std::move(*bytes);
  } else if (const char* variable = std::getenv("SPECULA_RESUME_SECRET")) {
    secret = variable;
  } else {
    return std::string();
  }
  while (!secret.empty() && (secret.back() == '\n' || secret.back() == '\r')) secret.pop_back();
  if (auto problem = session::SignedResume::secretProblem(secret)) return Error{*problem};
  return secret;
}

}  // namespace

int runServe(std::span<const std::string> arguments) {
  CommandLine options = serveOptions();
  if (auto exitCode = options.parseOrExit(arguments, fail)) return *exitCode;
  auto port = options.integer("port", 0, 65535);
  auto maxSessions = options.integer("max-sessions", 1, 4096);
  auto renderThreads = options.integer("render-threads", 1, 64);
  auto encodeThreads = options.integer("encode-threads", 1, 64);
  auto stillDelay = options.integer("still-delay", 0, 60000);
  auto maxFps = options.number("max-fps");
  auto maxSize = options.size("max-size", 16384);
  auto resumeLifetime = options.integer("resume-lifetime", 1, 7 * 24 * 3600);
  auto drainSeconds = options.integer("drain-seconds", 0, 3600);
  auto resumeSecret = readResumeSecret(options);
  session::SessionSettings sessionDefaults;  // every session starts with these
  const Status settings = parseSettingOptions(options, session::sessionSettingsSchema(), {}, sessionDefaults);
  applyImpliedOptions(options, sessionDefaults.reflection);
  for (const Status& status :
       {port ? Status{} : Error{port.error()}, maxSessions ? Status{} : Error{maxSessions.error()},
        renderThreads ? Status{} : Error{renderThreads.error()},
        encodeThreads ? Status{} : Error{encodeThreads.error()}, stillDelay ? Status{} : Error{stillDelay.error()},
        maxFps ? Status{} : Error{maxFps.error()}, maxSize ? Status{} : Error{maxSize.error()}, settings,
        resumeLifetime ? Status{} : Error{resumeLifetime.error()},
        drainSeconds ? Status{} : Error{drainSeconds.error()}, resumeSecret ? Status{} : Error{resumeSecret.error()}})
    if (!status) return fail(status.error());
  if (!(*maxFps > 0.0 && *maxFps <= 1000.0)) return fail("--max-fps expects a number in (0, 1000]");
  if (sessionDefaults.accuracyTarget > 0.0f && sessionDefaults.accuracySamples == 0)
    return fail("--accuracy-target needs the live estimate: drop --accuracy-samples 0, or the target");
  if (auto backend = parseGlOption(options.text("gl")); !backend) return fail(backend.error());

  net::ServerOptions serverOptions;
  serverOptions.bindAddress = options.text("bind");
  serverOptions.port = static_cast<std::uint16_t>(*port);
  serverOptions.token = options.has("token")           ? options.text("token")
                        : std::getenv("SPECULA_TOKEN") ? std::getenv("SPECULA_TOKEN")
                                                       : "";
  serverOptions.webRoot = options.text("web-root");
  serverOptions.publicMetrics = options.has("public-metrics");
  serverOptions.jsonDocuments["/settings-schema.json"] = session::settingsSchemaJson(sessionDefaults);
  if (auto problem = net::bindProblem(serverOptions)) return fail(*problem);  // before the slow scene and GL setup

  auto sceneChoice = parseSceneChoice(options);
  if (!sceneChoice) return fail(sceneChoice.error());
  auto scene = loadScene(options.text("scene"), *sceneChoice);
  if (!scene) return fail(scene.error());

  // Block the shutdown signals before any thread starts, so every thread inherits the mask and the main
  // thread alone receives them through sigwait.
  sigset_t shutdownSignals;
  sigemptyset(&shutdownSignals);
  sigaddset(&shutdownSignals, SIGTERM);
  sigaddset(&shutdownSignals, SIGINT);
  pthread_sigmask(SIG_BLOCK, &shutdownSignals, nullptr);
  std::signal(SIGPIPE, SIG_IGN);

  ServiceConfig config;
  config.scene = *scene;
  config.glBackend = options.text("gl");
  config.hub.maxSessions = *maxSessions;
  config.hub.maxWidth = maxSize->first;
  config.hub.maxHeight = maxSize->second;
  config.hub.stillDelay = std::chrono::milliseconds(*stillDelay);
  config.hub.maxFps = *maxFps;
  config.hub.defaults = sessionDefaults;
  config.hub.resumeSecret = *resumeSecret;
  config.hub.resumeLifetime = std::chrono::seconds(*resumeLifetime);
  config.hub.scheduler = {*renderThreads, *encodeThreads};
  config.server = serverOptions;
  auto service = Service::start(std::move(config));
  if (!service) return fail(service.error());

  const unsigned listeningPort = (*service)->port();
  std::printf("specula serve: scene '%s' at http://%s:%u/ (WebSocket /ws); listening on %s:%u\n",
              (*scene)->name.c_str(), serverOptions.bindAddress.c_str(), listeningPort,
              serverOptions.bindAddress.c_str(), listeningPort);
  std::fflush(stdout);

  int signal = 0;
  sigwait(&shutdownSignals, &signal);
  const char* name = signal == SIGTERM ? "SIGTERM" : "SIGINT";
  if (*drainSeconds > 0) {
    // Draining: balancers see /readyz fail and send new sessions elsewhere; open ones keep streaming
    // until their clients are closed below and resume on another instance. A second signal ends it early.
    (*service)->hub().refuseNewSessions();
    std::fprintf(stderr, "specula serve: %s: draining for %d s (%zu sessions; a second signal stops at once)\n", name,
                 *drainSeconds, (*service)->hub().sessionCount());
    const timespec wait{*drainSeconds, 0};
    sigtimedwait(&shutdownSignals, nullptr, &wait);
  }
  std::fprintf(stderr, "specula serve: %s: closing %zu sessions\n", name, (*service)->hub().sessionCount());
  (*service)->stop(kShutdownGrace);
  return 0;
}

}  // namespace specula::app
