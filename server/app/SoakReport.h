#pragma once
// The verdict and the outputs of `specula bench soak`: the samples over time as a table, CSV and JSON,
// the growth trends of memory, file descriptors and GL objects, and the server's counters checked
// against what the clients saw.
#include <optional>
#include <string>
#include <vector>

#include "LoadRun.h"
#include "app/GrowthTrend.h"
#include "app/ServerSampler.h"
#include "app/SoakClients.h"

namespace specula::app {

struct SoakRun {
  std::string scene;
  int sessions = 0, width = 0, height = 0;
  double runSeconds = 0.0, warmupSeconds = 0.0;
  std::vector<ServerSample> samples;       // while the clients ran; the first before they started
  std::optional<ServerSample> afterClose;  // once every client had closed and the server's sessions ended
  client::LoadReport load;
  std::vector<SoakRole> roles;  // per session
  SoakActions actions;
  std::optional<int> serverExit;  // after SIGTERM; nullopt when it did not exit in time
};

struct SoakVerdict {
  GrowthTrend rss, fds, glObjects;
  double promptLatencyP50 = 0.0, promptLatencyP99 = 0.0;  // sessions that read as frames come
  std::vector<std::string> checks;                        // "ok - ..." or "FAIL - ...", in order
  std::vector<std::string> failures;                      // what failed, for the last line
};

SoakVerdict judgeSoak(const SoakRun& run);
std::string soakTableRow(const ServerSample& sample);  // one line of the table, as it is sampled
std::string soakTableHeader();
std::string soakSummary(const SoakRun& run, const SoakVerdict& verdict);
std::string soakCsv(const SoakRun& run);
std::string soakJson(const SoakRun& run, const SoakVerdict& verdict);

}  // namespace specula::app
