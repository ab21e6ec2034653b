#include "base/CommandLine.h"

#include <iostream>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

namespace specula {

namespace {

std::optional<double> parseFinite(std::string_view text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace

CommandLine::CommandLine(std::string usage, std::string summary, std::vector<OptionSpec> options)
    : usage_(std::move(usage)), summary_(std::move(summary)), options_(std::move(options)) {}

const OptionSpec* CommandLine::find(const std::string& name) const {
  for (const OptionSpec& option : options_)
    if (option.name == name) return &option;
  return nullptr;
}

Status CommandLine::parse(std::span<const std::string> arguments) {
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& argument = arguments[i];
    if (argument == "--help" || argument == "-h") {
      helpRequested_ = true;
      continue;
    }
    if (!argument.starts_with("--"))
      return Error{"unexpected argument '" + argument + "'; options start with -- (see --help)"};
    std::string name = argument.substr(2);
    std::optional<std::string> value;
    if (const std::size_t equals = name.find('='); equals != std::string::npos) {
      value = name.substr(equals + 1);
      name.resize(equals);
    }
    const OptionSpec* option = find(name);
    if (!option) return Error{"unknown option --" + name + " (see --help)"};
    if (option->valueName.empty()) {
      if (value) return Error{"--" + name + " takes no value"};
      values_[name] = "";
      continue;
    }
    if (!value) {
      if (i + 1 >= arguments.size()) return Error{"--" + name + " needs a value: --" + name + " " + option->valueName};
      value = arguments[++i];
    }
    values_[name] = *value;
  }
  return {};
}

std::optional<int> CommandLine::parseOrExit(std::span<const std::string> arguments,
                                            const std::function<int(const std::string&)>& fail) {
  if (Status status = parse(arguments); !status) return fail(status.error());
  if (!helpRequested_) return std::nullopt;
  std::cout << help();
  return 0;
}

std::string CommandLine::help() const {
  std::ostringstream out;
  out << "usage: " << usage_ << "\n\n" << summary_ << "\n\noptions:\n";
  for (const OptionSpec& option : options_) {
    std::string left = "  --" + option.name + (option.valueName.empty() ? "" : " " + option.valueName);
    out << left << std::string(left.size() < 30 ? 30 - left.size() : 1, ' ') << option.help;
    if (!option.defaultValue.empty()) out << " (default: " << option.defaultValue << ")";
    out << "\n";
  }
  out << "  --help                      print this help\n";
  return out.str();
}

std::string CommandLine::text(const std::string& name) const {
  if (auto found = values_.find(name); found != values_.end()) return found->second;
  const OptionSpec* option = find(name);
  return option ? option->defaultValue : "";
}

Result<double> CommandLine::number(const std::string& name) const {
  const std::string value = text(name);
  if (auto parsed = parseFinite(value)) return *parsed;
  return Error{"--" + name + " expects a finite number, got '" + value + "'"};
}

namespace {

Result<int> parseInteger(const std::string& name, const std::string& value, int low, int high) {
  int parsed = 0;
  const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), parsed);
  if (error != std::errc() || end != value.data() + value.size() || parsed < low || parsed > high)
    return Error{"--" + name + " expects an integer in [" + std::to_string(low) + ", " + std::to_string(high) +
                 "], got '" + value + "'"};
  return parsed;
}

Result<std::pair<int, int>> parseSize(const std::string& name, const std::string& value, int maxSide) {
  const std::size_t x = value.find('x');
  int width = 0, height = 0;
  if (x != std::string::npos) {
    const auto w = std::from_chars(value.data(), value.data() + x, width);
    const auto h = std::from_chars(value.data() + x + 1, value.data() + value.size(), height);
    if (w.ec == std::errc() && w.ptr == value.data() + x && h.ec == std::errc() &&
        h.ptr == value.data() + value.size() && width >= 1 && height >= 1 && width <= maxSide && height <= maxSide)
      return std::pair{width, height};
  }
  return Error{"--" + name + " expects WIDTHxHEIGHT with sides in [1, " + std::to_string(maxSide) +
               "] like 640x480, got '" + value + "'"};
}

// Applies `parse` to each comma-separated item; fails on the first bad one or on an empty list.
template <class T, class Parse>
Result<std::vector<T>> parseList(const std::string& name, const std::string& value, Parse parse) {
  std::vector<T> items;
  std::size_t start = 0;
  while (start <= value.size()) {
    const std::size_t comma = std::min(value.find(',', start), value.size());
    if (comma > start) {
      auto item = parse(value.substr(start, comma - start));
      if (!item) return Error{item.error()};
      items.push_back(*item);
    }
    start = comma + 1;
  }
  if (items.empty()) return Error{"--" + name + " lists nothing"};
  return items;
}

}  // namespace

Result<int> CommandLine::integer(const std::string& name, int low, int high) const {
  return parseInteger(name, text(name), low, high);
}

Result<std::vector<int>> CommandLine::integerList(const std::string& name, int low, int high) const {
  return parseList<int>(name, text(name), [&](const std::string& item) { return parseInteger(name, item, low, high); });
}

Result<glm::vec3> CommandLine::vector3(const std::string& name) const {
  const std::string value = text(name);
  glm::vec3 result(0.0f);
  std::string_view rest = value;
  for (int axis = 0; axis < 3; ++axis) {
    const std::size_t comma = rest.find(',');
    const bool last = axis == 2;
    if (last != (comma == std::string_view::npos)) break;
    const auto parsed = parseFinite(rest.substr(0, comma));
    if (!parsed) break;
    result[axis] = static_cast<float>(*parsed);
    if (last) return result;
    rest.remove_prefix(comma + 1);
  }
  return Error{"--" + name + " expects three comma-separated numbers like 1,3,3.5, got '" + value + "'"};
}

Result<std::pair<int, int>> CommandLine::size(const std::string& name, int maxSide) const {
  return parseSize(name, text(name), maxSide);
}

Result<std::vector<std::pair<int, int>>> CommandLine::sizeList(const std::string& name, int maxSide) const {
  return parseList<std::pair<int, int>>(name, text(name),
                                        [&](const std::string& item) { return parseSize(name, item, maxSide); });
}

}  // namespace specula
