#include "session/ResumeStore.h"

#include <algorithm>
#include <random>

namespace specula::session {

void ResumeStore::dropExpired(Clock::time_point now) {
  std::erase_if(entries_, [&](const auto& entry) { return now - entry.second.savedAt > lifetime_; });
}

void ResumeStore::save(const std::string& token, SessionState state, Clock::time_point now) {
  std::lock_guard lock(mutex_);
  dropExpired(now);
  while (!entries_.empty() && entries_.size() >= capacity_) {
    auto oldest = std::min_element(entries_.begin(), entries_.end(),
                                   [](const auto& a, const auto& b) { return a.second.savedAt < b.second.savedAt; });
    entries_.erase(oldest);
  }
  if (capacity_ > 0) entries_[token] = Entry{std::move(state), now};
}

std::optional<SessionState> ResumeStore::take(const std::string& token, Clock::time_point now) {
  std::lock_guard lock(mutex_);
  dropExpired(now);
  auto found = entries_.find(token);
  if (found == entries_.end()) return std::nullopt;
  SessionState state = std::move(found->second.state);
  entries_.erase(found);
  return state;
}

std::size_t ResumeStore::size() const {
  std::lock_guard lock(mutex_);
  return entries_.size();
}

std::string randomToken() {
  std::random_device device;  // the kernel's CSPRNG on Linux: tokens must not be guessable
  constexpr char kHex[] = "0123456789abcdef";
  std::string token;
  for (int word = 0; word < 4; ++word) {
    std::uint32_t bits = device();
    for (int i = 0; i < 8; ++i, bits >>= 4) token += kHex[bits & 15];
  }
  return token;
}

}  // namespace specula::session
