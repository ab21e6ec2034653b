#pragma once
// The clients of `specula bench soak`, as a LoadOptions::script: each session plays one role in turn
// (steady, slow reader, reader that stops, client that vanishes, settings changer), and every session
// joins the reconnect storms, when all of them drop their connections at once and resume.
#include <array>
#include <atomic>
#include <string>
#include <vector>

#include "ResumingClient.h"
#include "base/Result.h"

namespace specula::app {

enum class SoakRole { Steady, SlowReader, Stopper, Vanisher, SettingsChanger };
constexpr std::array kSoakRoles = {SoakRole::Steady, SoakRole::SlowReader, SoakRole::Stopper, SoakRole::Vanisher,
                                   SoakRole::SettingsChanger};
std::string roleName(SoakRole role);

struct SoakTiming {
  double runSeconds = 600.0;
  int storms = 4;                                         // evenly spread: at 1/5, 2/5, 3/5 and 4/5 of the run
  double slowReadPauseSeconds = 0.25;                     // a slow reader's wait before each read
  double stopEverySeconds = 30.0, stopForSeconds = 15.0;  // longer than the server's 5 s write deadline
  // A stopping reader's receive buffer: a thin pipe that a frame or two fills, so the server's write
  // waits, newer frames replace the one queued, and the deadline drops the connection (which resumes).
  // Loopback's autotuned receive buffers (up to tcp_rmem's 32 MiB) hold a 15 s pause at a few frames a second.
  int stopperReceiveBufferBytes = 8 << 10;
  double vanishEverySeconds = 10.0;
  double settingsEverySeconds = 3.0;
};

struct SoakActions {  // what the clients did, for the report
  int storms = 0, drops = 0, stops = 0, settingsSent = 0;
  int stopsDropped = 0;  // stops during which the server dropped the connection (the client had to reconnect)
};

class SoakClients {
 public:
  SoakClients(int sessions, SoakTiming timing);
  static SoakRole role(int session) { return kSoakRoles[static_cast<std::size_t>(session) % kSoakRoles.size()]; }
  // LoadOptions::sessionReconnect: the connection each role makes.
  client::ReconnectPolicy connection(int session, client::ReconnectPolicy policy) const;
  // LoadOptions::script: called by session `session`'s thread only.
  Status act(int session, double seconds, client::ResumingClient& client);
  SoakActions actions() const;  // once the sessions' threads have ended

 private:
  struct SessionState {
    double nextEvent = 0.0;  // the role's next stop, vanish or settings change
    int stormsJoined = 0;
    std::size_t settingsIndex = 0;
  };
  SoakTiming timing_;
  std::vector<SessionState> states_;
  std::atomic<int> drops_{0}, stops_{0}, stopsDropped_{0}, settingsSent_{0};
};

}  // namespace specula::app
