#include "bench/ReportFormat.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace specula::bench {

namespace {

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// A scene name from a user's file may not be UTF-8: replaced, so the JSON stays valid.
std::string jsonText(const nlohmann::ordered_json& value) {
  return value.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

// A number cell holds the text CSV shows, itself a JSON literal: read back, JSON gets the same value,
// rounded alike, and the same type (integer, decimal, true or false).
nlohmann::ordered_json jsonValue(const ReportCell& cell) {
  if (cell.text) return cell.value;
  if (cell.value.empty()) return nullptr;
  return nlohmann::ordered_json::parse(cell.value);
}

}  // namespace

std::string number(double value, int decimals) {
  if (!std::isfinite(value)) return "";
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::string significant(double value) {
  if (!std::isfinite(value)) return "";
  char text[64];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string optionalNumber(const std::optional<double>& value, int decimals) {
  return value ? number(*value, decimals) : "";
}

std::string orDash(const std::string& text) { return text.empty() ? "-" : text; }

std::string csvFromRows(const ReportRow& header, std::span<const ReportRow> rows) {
  std::string csv;
  for (std::size_t i = 0; i < header.size(); ++i) csv += (i ? "," : "") + header[i].name;
  csv += "\n";
  for (const ReportRow& row : rows) {
    for (std::size_t i = 0; i < row.size(); ++i) csv += (i ? "," : "") + csvField(row[i].value);
    csv += "\n";
  }
  return csv;
}

std::string jsonFromRows(const std::string& key, std::span<const ReportRow> rows) {
  // nlohmann writes every name and value; the layout, an object a line, keeps the file diffable and greppable.
  std::string json = "{" + jsonText(key) + ": [";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    json += r ? ",\n  {" : "\n  {";
    for (std::size_t i = 0; i < rows[r].size(); ++i)
      json += (i ? ", " : "") + jsonText(rows[r][i].name) + ": " + jsonText(jsonValue(rows[r][i]));
    json += "}";
  }
  return json + "\n]}\n";
}

}  // namespace specula::bench
