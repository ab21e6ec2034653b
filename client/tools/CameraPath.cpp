#include "CameraPath.h"

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

namespace specula::client {

namespace {

// Keys must exist, be finite, have increasing times, a valid camera and scene time on all or none.
Status checkKeys(const std::vector<PathKey>& keys, const std::string& where) {
  if (keys.empty()) return Error{where + ": the path has no keys"};
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const PathKey& k = keys[i];
    const std::string key = where + ": key " + std::to_string(i + 1);
    for (float v :
         {k.eye.x, k.eye.y, k.eye.z, k.target.x, k.target.y, k.target.z, k.up.x, k.up.y, k.up.z, k.fovDegrees})
      if (!std::isfinite(v)) return Error{key + " has a non-finite number"};
    if (!std::isfinite(k.time) || (k.sceneTime && !std::isfinite(*k.sceneTime)))
      return Error{key + " has a non-finite time"};
    if (i > 0 && k.time <= keys[i - 1].time) return Error{key + ": times must increase strictly"};
    if (glm::length(k.eye - k.target) < 1e-6f) return Error{key + ": eye and target coincide"};
    if (!(k.fovDegrees > 0.0f && k.fovDegrees < 180.0f)) return Error{key + ": fov must be in (0, 180) degrees"};
    if (k.sceneTime.has_value() != keys.front().sceneTime.has_value())
      return Error{key + ": scene_time must be on every key or on none"};
  }
  return {};
}

}  // namespace

PathKey CameraPath::at(double time) const {
  if (time <= keys.front().time) return keys.front();
  if (time >= keys.back().time) return keys.back();
  std::size_t next = 1;
  while (keys[next].time < time) ++next;
  const PathKey& a = keys[next - 1];
  const PathKey& b = keys[next];
  const float s = static_cast<float>((time - a.time) / (b.time - a.time));
  PathKey out;
  out.time = time;
  out.eye = glm::mix(a.eye, b.eye, s);
  out.target = glm::mix(a.target, b.target, s);
  out.up = glm::mix(a.up, b.up, s);
  out.fovDegrees = a.fovDegrees + (b.fovDegrees - a.fovDegrees) * s;
  if (a.sceneTime) out.sceneTime = *a.sceneTime + (*b.sceneTime - *a.sceneTime) * s;
  return out;
}

Result<CameraPath> parseCameraPathJson(const std::string& text) {
  const nlohmann::json root = nlohmann::json::parse(text, nullptr, false);
  if (root.is_discarded() || !root.is_object() || !root.contains("keys") || !root["keys"].is_array())
    return Error{"a JSON path must be an object with a \"keys\" array"};
  CameraPath path;
  for (std::size_t i = 0; i < root["keys"].size(); ++i) {
    const nlohmann::json& item = root["keys"][i];
    const std::string key = "key " + std::to_string(i + 1);
    auto vector = [&](const char* name, glm::vec3& out, bool required) -> Status {
      if (!item.contains(name)) return required ? Status(Error{key + " lacks \"" + name + "\""}) : Status{};
      const nlohmann::json& v = item[name];
      if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
        return Error{key + ": \"" + name + "\" must be [x, y, z]"};
      out = {v[0].get<float>(), v[1].get<float>(), v[2].get<float>()};
      return {};
    };
    PathKey k;
    if (!item.is_object() || !item.contains("time") || !item["time"].is_number())
      return Error{key + " needs a numeric \"time\""};
    k.time = item["time"].get<double>();
    for (auto [name, field, required] :
         {std::tuple{"eye", &k.eye, true}, {"target", &k.target, true}, {"up", &k.up, false}})
      if (Status status = vector(name, *field, required); !status) return Error{status.error()};
    if (item.contains("fov")) {
      if (!item["fov"].is_number()) return Error{key + ": \"fov\" must be a number"};
      k.fovDegrees = item["fov"].get<float>();
    }
    if (item.contains("scene_time")) {
      if (!item["scene_time"].is_number()) return Error{key + ": \"scene_time\" must be a number"};
      k.sceneTime = item["scene_time"].get<double>();
    }
    path.keys.push_back(k);
  }
  if (Status status = checkKeys(path.keys, "path"); !status) return Error{status.error()};
  return path;
}

Result<CameraPath> parseCameraPathCsv(const std::string& text) {
  std::istringstream lines(text);
  std::string header;
  if (!std::getline(lines, header)) return Error{"the CSV path is empty: it needs a header line"};
  std::map<std::string, std::size_t> column;
  {
    std::istringstream cells(header);
    std::size_t index = 0;
    for (std::string name; std::getline(cells, name, ',');) {
      while (!name.empty() && (name.back() == '\r' || name.back() == ' ')) name.pop_back();
      column[name] = index++;
    }
  }
  for (const char* required : {"time", "eye_x", "eye_y", "eye_z", "target_x", "target_y", "target_z"})
    if (!column.contains(required)) return Error{std::string("the CSV header lacks column '") + required + "'"};
  CameraPath path;
  std::size_t lineNumber = 1;
  for (std::string line; std::getline(lines, line);) {
    ++lineNumber;
    if (line.empty() || line == "\r") continue;
    std::vector<double> cells;
    std::istringstream stream(line);
    for (std::string cell; std::getline(stream, cell, ',');) {
      char* end = nullptr;
      const double value = std::strtod(cell.c_str(), &end);
      if (end == cell.c_str()) return Error{"line " + std::to_string(lineNumber) + ": '" + cell + "' is not a number"};
      cells.push_back(value);
    }
    auto get = [&](const char* name, double fallback) {
      auto found = column.find(name);
      return found != column.end() && found->second < cells.size() ? cells[found->second] : fallback;
    };
    if (cells.size() < column.size())
      return Error{"line " + std::to_string(lineNumber) + " has fewer cells than the header"};
    PathKey k;
    k.time = get("time", 0.0);
    k.eye = glm::vec3(get("eye_x", 0), get("eye_y", 0), get("eye_z", 0));
    k.target = glm::vec3(get("target_x", 0), get("target_y", 0), get("target_z", 0));
    k.up = glm::vec3(get("up_x", 0), get("up_y", 1), get("up_z", 0));
    k.fovDegrees = static_cast<float>(get("fov", 45));
    if (column.contains("scene_time")) k.sceneTime = get("scene_time", 0);
    path.keys.push_back(k);
  }
  if (Status status = checkKeys(path.keys, "CSV path"); !status) return Error{status.error()};
  return path;
}

Result<CameraPath> loadCameraPath(const std::string& file) {
  const bool csv = file.size() >= 4 && file.substr(file.size() - 4) == ".csv";
  const bool json = file.size() >= 5 && file.substr(file.size() - 5) == ".json";
  if (!csv && !json) return Error{"'" + file + "': a path file ends in .json or .csv"};
  std::ifstream stream(file, std::ios::binary);
  if (!stream) return Error{"cannot read the path file '" + file + "'"};
  std::stringstream text;
  text << stream.rdbuf();
  auto path = csv ? parseCameraPathCsv(text.str()) : parseCameraPathJson(text.str());
  if (!path) return Error{"'" + file + "': " + path.error()};
  return path;
}

}  // namespace specula::client
