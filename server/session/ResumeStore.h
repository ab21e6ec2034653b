#pragma once
// Session states kept after a disconnect, so a client that reconnects with its token gets them back.
#include <chrono>
#include <cstddef>
#include <map>
#include <mutex>
#include <optional>
#include <string>

#include "session/SessionState.h"

namespace specula::session {

class ResumeStore {
 public:
  ResumeStore(std::size_t capacity, std::chrono::seconds lifetime) : capacity_(capacity), lifetime_(lifetime) {}

  // Keeps `state` under `token`; beyond capacity the oldest entry goes.
  void save(const std::string& token, SessionState state, Clock::time_point now);
  // Takes the state saved under `token` (a token resumes once), or nullopt if unknown or expired.
  std::optional<SessionState> take(const std::string& token, Clock::time_point now);
  std::size_t size() const;

 private:
  struct Entry {
    SessionState state;
    Clock::time_point savedAt;
  };
  void dropExpired(Clock::time_point now);

  std::size_t capacity_;
  std::chrono::seconds lifetime_;
  mutable std::mutex mutex_;
  std::map<std::string, Entry> entries_;
};

// 128 random bits as 32 hex digits: session ids and resume tokens.
std::string randomToken();

}  // namespace specula::session
