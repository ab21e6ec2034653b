#include "session/ServiceMetrics.h"

namespace specula::session {

std::string ServiceMetrics::prometheusText() const {
  std::string out;
  auto sample = [&](const char* name, const char* type, const char* help, double value) {
    net::appendPrometheusSample(out, name, type, help, value);
  };
  sample("specula_sessions", "gauge", "Open sessions.", static_cast<double>(sessions.load()));
  sample("specula_sessions_opened_total", "counter", "Sessions that completed hello.",
         static_cast<double>(sessionsOpened.load()));
  sample("specula_sessions_refused_total", "counter", "Connections refused at the session limit or on shutdown.",
         static_cast<double>(sessionsRefused.load()));
  sample("specula_sessions_resumed_total", "counter", "Sessions restored from a resume token.",
         static_cast<double>(sessionsResumed.load()));
  sample("specula_resumes_refused_total", "counter",
         "Resume tokens refused (unknown, expired, altered, another secret or scene).",
         static_cast<double>(resumesRefused.load()));
  sample("specula_frames_sent_total", "counter", "Frames written to clients.", static_cast<double>(framesSent.load()));
  sample("specula_frames_skipped_total", "counter", "Frames replaced by a newer one before they were sent.",
         static_cast<double>(framesSkipped.load()));
  sample("specula_frame_bytes_sent_total", "counter", "Bytes of frame messages written to clients.",
         static_cast<double>(frameBytesSent.load()));
  sample("specula_protocol_errors_total", "counter", "Connections closed for malformed or oversized messages.",
         static_cast<double>(protocolErrors.load()));
  sample("specula_write_timeouts_total", "counter",
         "Connections dropped because a write waited past the write deadline (the client stopped reading).",
         static_cast<double>(writeTimeouts.load()));
  sample("specula_render_failures_total", "counter", "Frames the renderer could not produce.",
         static_cast<double>(renderFailures.load()));
  sample("specula_accuracy_failures_total", "counter", "Frames whose live accuracy estimate could not be traced.",
         static_cast<double>(accuracyFailures.load()));
  renderMs.appendPrometheus(out, "specula_render_milliseconds", "Wall-clock render time per frame.");
  encodeMs.appendPrometheus(out, "specula_encode_milliseconds", "JPEG encode time per frame.");
  latencyMs.appendPrometheus(out, "specula_input_to_frame_milliseconds",
                             "From an input's arrival to the frame that reflects it being queued for sending.");
  frameBytes.appendPrometheus(out, "specula_frame_bytes", "Size of each frame message.");
  accuracyMismatch.appendPrometheus(out, "specula_accuracy_mismatch_percent",
                                    "Live accuracy estimate per sampled frame: the share of its sampled mirror pixels "
                                    "that differ from the exact reference, percent.");
  accuracyMs.appendPrometheus(out, "specula_accuracy_milliseconds",
                              "Server CPU time of each frame's live accuracy estimate (beside rendering).");
  return out;
}

}  // namespace specula::session
