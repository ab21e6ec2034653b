#include "app/SoakReport.h"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "base/Percentile.h"

namespace specula::app {

namespace {

// What growth after the warm-up the soak tolerates, and why. The t-statistic of 3 on top keeps a wobble
// that happens to end high from counting as a trend.
// Resident memory: llvmpipe compiles shader variants and glibc's allocator keeps per-thread arenas, so RSS
// settles over the first minute and then wanders by a few MiB between samples. 16 MiB plus 5 % is far
// below what a real leak adds in ten minutes: one 640x360 RGBA frame (0.9 MiB) leaked every 10 s is 49 MiB.
constexpr GrowthLimit kRssLimit{16.0, 0.05, 3.0};
// File descriptors: a few sockets can be closing or opening while a sample is taken; one leaked per
// reconnect would add hundreds.
constexpr GrowthLimit kFdLimit{3.0, 0.0, 3.0};
// GL objects: targets follow sessions and their render sizes, so the count moves as sessions come and go;
// one object leaked per settings change or per reconnect would add hundreds.
constexpr GrowthLimit kGlLimit{8.0, 0.0, 3.0};

std::string format(const char* pattern, auto... values) {
  char text[512];
  std::snprintf(text, sizeof text, pattern, values...);
  return text;
}

GrowthTrend trendOf(const SoakRun& run, double ServerSample::*field, const GrowthLimit& limit) {
  std::vector<double> seconds, values;
  for (const ServerSample& sample : run.samples) {
    seconds.push_back(sample.seconds);
    values.push_back(sample.*field);
  }
  return growthTrend(seconds, values, run.warmupSeconds, limit);
}

std::string trendLine(const char* what, const char* unit, double first, double last, const GrowthTrend& trend) {
  return format(
      "%-11s %8.1f at start, %8.1f at end; after the warm-up %+.2f %s a minute, %+.1f %s over %zu samples "
      "(tolerated %.1f, t = %.1f)",
      what, first, last, trend.slopePerSecond * 60.0, unit, trend.growth, unit, trend.samples, trend.tolerance,
      trend.tStatistic);
}

}  // namespace

SoakVerdict judgeSoak(const SoakRun& run) {
  SoakVerdict verdict;
  const auto check = [&](bool passed, const std::string& what, const std::string& failure) {
    verdict.checks.push_back((passed ? "ok - " : "FAIL - ") + what);
    if (!passed) verdict.failures.push_back(failure);
  };
  verdict.rss = trendOf(run, &ServerSample::rssMiB, kRssLimit);
  verdict.fds = trendOf(run, &ServerSample::fds, kFdLimit);
  verdict.glObjects = trendOf(run, &ServerSample::glObjects, kGlLimit);
  const auto enough = [&](const GrowthTrend& trend) { return trend.samples >= 3; };
  check(enough(verdict.rss), "at least 3 samples after the warm-up", "too few samples after the warm-up to judge");
  check(!verdict.rss.grows, "resident memory does not grow", "resident memory grew");
  check(!verdict.fds.grows, "open file descriptors do not grow", "open file descriptors grew");
  check(!verdict.glObjects.grows, "live GL objects do not grow", "live GL objects grew");

  const client::LoadReport& load = run.load;
  int reconnects = 0, resumed = 0, refused = 0, silent = 0;
  std::vector<double> prompt;
  for (std::size_t i = 0; i < load.sessions.size(); ++i) {
    const client::SessionLoad& session = load.sessions[i];
    reconnects += session.reconnects;
    resumed += session.resumed;
    refused += session.resumesRefused;
    silent += session.frames == 0 ? 1 : 0;
    const SoakRole role = run.roles.at(i);
    if (role == SoakRole::Steady || role == SoakRole::Vanisher || role == SoakRole::SettingsChanger)
      prompt.insert(prompt.end(), session.latencyMs.begin(), session.latencyMs.end());
  }
  verdict.promptLatencyP50 = nearestRankPercentile(prompt, 0.5);
  verdict.promptLatencyP99 = nearestRankPercentile(prompt, 0.99);
  check(load.errors == 0,
        format("no session ended in an error (%llu did)", static_cast<unsigned long long>(load.errors)),
        "sessions ended in errors");
  check(silent == 0, format("every session received frames (%d received none)", silent), "sessions starved");
  const ServerSample server = run.afterClose.value_or(run.samples.empty() ? ServerSample{} : run.samples.back());
  check(server.framesSent >= static_cast<double>(load.frames),
        format("frames sent %.0f >= frames the clients received %llu", server.framesSent,
               static_cast<unsigned long long>(load.frames)),
        "the server counted fewer frames sent than the clients received");
  // A resume the server counted can miss its client only when that connection dropped before the welcome.
  check(server.sessionsResumed >= resumed && server.sessionsResumed <= reconnects,
        format("resumes counted %.0f: at least the %d welcomes that said resumed, at most the %d reconnects",
               server.sessionsResumed, resumed, reconnects),
        "the server's resume count disagrees with the clients'");
  check(server.resumesRefused >= refused && server.sessionsResumed + server.resumesRefused <= reconnects,
        format("resumes refused %.0f: at least the %d the clients were told, and with the resumed at most the "
               "reconnects",
               server.resumesRefused, refused),
        "the server's refused-resume count disagrees with the clients'");
  // Each stop the server ended is one write timeout at least; and some stop must have lasted long enough for
  // one, or the deadline went untested (how many do depends on the frame rate: a frame or two fill the pipe).
  check(server.writeTimeouts >= run.actions.stopsDropped && (run.actions.stops == 0 || run.actions.stopsDropped > 0),
        format("connections dropped at the write deadline %.0f: at least the %d stops (of %d) the server ended",
               server.writeTimeouts, run.actions.stopsDropped, run.actions.stops),
        "the server's write timeouts disagree with the stopped readers'");
  check(run.afterClose && run.afterClose->sessions == 0.0,
        format("no session left open once the clients closed (%.0f)", run.afterClose ? run.afterClose->sessions : -1.0),
        "sessions stayed open after their clients closed");
  check(run.serverExit == 0, "the server exited with status 0 on SIGTERM",
        "the server did not exit cleanly on SIGTERM");
  return verdict;
}

std::string soakTableHeader() {
  return "     s   RSS MiB   fds  GL objects  sessions  frames sent  received  skipped  timeouts  resumed\n";
}

std::string soakTableRow(const ServerSample& s) {
  return format("%6.0f  %8.1f  %4.0f  %10.0f  %8.0f  %11.0f  %8llu  %7.0f  %8.0f  %7.0f\n", s.seconds, s.rssMiB, s.fds,
                s.glObjects, s.sessions, s.framesSent, static_cast<unsigned long long>(s.framesReceived),
                s.framesSkipped, s.writeTimeouts, s.sessionsResumed);
}

std::string soakSummary(const SoakRun& run, const SoakVerdict& verdict) {
  const client::LoadReport& load = run.load;
  const ServerSample first = run.samples.empty() ? ServerSample{} : run.samples.front();
  const ServerSample last = run.samples.empty() ? ServerSample{} : run.samples.back();
  std::string out;
  out += format(
      "%d sessions at %dx%d on %s for %.0f s (warm-up %.0f s): %d storms, %d abrupt drops, %d stops, "
      "%d settings changes\n",
      run.sessions, run.width, run.height, run.scene.c_str(), run.runSeconds, run.warmupSeconds, run.actions.storms,
      run.actions.drops, run.actions.stops, run.actions.settingsSent);
  out += format(
      "frames delivered %llu (%.1f fps a session, slowest %.1f), %.0f skipped by the server; %.0f connections "
      "dropped at the write deadline\n",
      static_cast<unsigned long long>(load.frames), load.fpsMean, load.fpsMin, last.framesSkipped, last.writeTimeouts);
  out += format(
      "input-to-frame latency ms: sessions reading promptly p50 %.0f p99 %.0f; all p50 %.0f p99 %.0f "
      "max %.0f\n",
      verdict.promptLatencyP50, verdict.promptLatencyP99, load.latencyP50, load.latencyP99, load.latencyMax);
  out += trendLine("RSS MiB", "MiB", first.rssMiB, last.rssMiB, verdict.rss) + "\n";
  out += trendLine("fds", "fds", first.fds, last.fds, verdict.fds) + "\n";
  out += trendLine("GL objects", "objects", first.glObjects, last.glObjects, verdict.glObjects) + "\n";
  if (run.afterClose)
    out += format("after the clients closed: RSS %.1f MiB, %.0f fds, %.0f GL objects, %.0f sessions\n",
                  run.afterClose->rssMiB, run.afterClose->fds, run.afterClose->glObjects, run.afterClose->sessions);
  for (const std::string& line : verdict.checks) out += line + "\n";
  if (verdict.failures.empty()) return out + "PASS\n";
  out += "FAIL:";
  for (const std::string& failure : verdict.failures) out += " " + failure + ";";
  return out + "\n";
}

std::string soakCsv(const SoakRun& run) {
  std::string csv =
      "seconds,rss_mib,fds,gl_objects,sessions,frames_sent,frames_received,frames_skipped,write_timeouts,"
      "sessions_opened,sessions_resumed,resumes_refused\n";
  for (const ServerSample& s : run.samples)
    csv += format("%.1f,%.2f,%.0f,%.0f,%.0f,%.0f,%llu,%.0f,%.0f,%.0f,%.0f,%.0f\n", s.seconds, s.rssMiB, s.fds,
                  s.glObjects, s.sessions, s.framesSent, static_cast<unsigned long long>(s.framesReceived),
                  s.framesSkipped, s.writeTimeouts, s.sessionsOpened, s.sessionsResumed, s.resumesRefused);
  return csv;
}

std::string soakJson(const SoakRun& run, const SoakVerdict& verdict) {
  const auto trend = [](const GrowthTrend& t) {
    return nlohmann::json{{"samples", t.samples},        {"slope_per_minute", t.slopePerSecond * 60.0},
                          {"start", t.startLevel},       {"end", t.endLevel},
                          {"growth", t.growth},          {"tolerance", t.tolerance},
                          {"t_statistic", t.tStatistic}, {"grows", t.grows}};
  };
  nlohmann::json samples = nlohmann::json::array();
  for (const ServerSample& s : run.samples)
    samples.push_back({{"seconds", s.seconds},
                       {"rss_mib", s.rssMiB},
                       {"fds", s.fds},
                       {"gl_objects", s.glObjects},
                       {"sessions", s.sessions},
                       {"frames_sent", s.framesSent},
                       {"frames_received", s.framesReceived},
                       {"frames_skipped", s.framesSkipped},
                       {"write_timeouts", s.writeTimeouts},
                       {"sessions_opened", s.sessionsOpened},
                       {"sessions_resumed", s.sessionsResumed},
                       {"resumes_refused", s.resumesRefused}});
  nlohmann::json roles = nlohmann::json::array();
  for (SoakRole role : run.roles) roles.push_back(roleName(role));
  const nlohmann::json out = {
      {"scene", run.scene},
      {"run_seconds", run.runSeconds},
      {"warmup_seconds", run.warmupSeconds},
      {"roles", roles},
      {"actions",
       {{"storms", run.actions.storms},
        {"drops", run.actions.drops},
        {"stops", run.actions.stops},
        {"stops_the_server_ended", run.actions.stopsDropped},
        {"settings_changes", run.actions.settingsSent}}},
      {"samples", samples},
      {"trends",
       {{"rss_mib", trend(verdict.rss)}, {"fds", trend(verdict.fds)}, {"gl_objects", trend(verdict.glObjects)}}},
      {"latency_ms_prompt_p50", verdict.promptLatencyP50},
      {"latency_ms_prompt_p99", verdict.promptLatencyP99},
      {"checks", verdict.checks},
      {"passed", verdict.failures.empty()},
      {"load", nlohmann::json::parse(client::loadReportJson(run.load))},
  };
  return out.dump(2) + "\n";
}

}  // namespace specula::app
