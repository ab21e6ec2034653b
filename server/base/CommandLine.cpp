#include "base/CommandLine.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <stdexcept>

namespace specula {

namespace {

std::optional<double> parseFinite(std::string_view text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// CLI11's help with the command's own usage line first, then its summary.
class HelpFormatter : public CLI::Formatter {
 public:
  explicit HelpFormatter(std::string usage) : usage_(std::move(usage)) { column_width(30); }
  std::string make_description(const CLI::App*) const override { return ""; }
  std::string make_usage(const CLI::App* app, std::string) const override {
    return "usage: " + usage_ + "\n\n" + app->get_description() + "\n";
  }

 private:
  std::string usage_;
};

}  // namespace

CommandLine::CommandLine(std::string usage, std::string summary, std::vector<OptionSpec> options)
    : options_(std::move(options)), app_(std::make_unique<CLI::App>(std::move(summary))) {
  app_->formatter(std::make_shared<HelpFormatter>(std::move(usage)));
  app_->set_help_flag("-h,--help", "print this help");
  for (const OptionSpec& option : options_) {
    const std::string help =
        option.help + (option.defaultValue.empty() ? "" : " (default: " + option.defaultValue + ")");
    CLI::Option* added = option.valueName.empty() ? app_->add_flag("--" + option.name, help)
                                                  : app_->add_option("--" + option.name, values_[option.name], help)
                                                        ->type_name(option.valueName)
                                                        ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    added->allow_extra_args(false);
  }
}

CommandLine::CommandLine(CommandLine&&) noexcept = default;
CommandLine& CommandLine::operator=(CommandLine&&) noexcept = default;
CommandLine::~CommandLine() = default;

const OptionSpec& CommandLine::find(const std::string& name) const {
  for (const OptionSpec& option : options_)
    if (option.name == name) return option;
  throw std::logic_error("the command asked for --" + name + ", which its option table does not declare");
}

Status CommandLine::parse(std::span<const std::string> arguments) {
  std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());  // CLI11 takes them last first
  try {
    app_->parse(reversed);
  } catch (const CLI::CallForHelp&) {
    helpRequested_ = true;
  } catch (const CLI::ExtrasError&) {
    for (const std::string& extra : app_->remaining()) {
      if (extra.starts_with("--")) return Error{"unknown option " + extra.substr(0, extra.find('=')) + " (see --help)"};
      return Error{"unexpected argument '" + extra + "'; options start with -- (see --help)"};
    }
    return Error{"unexpected arguments (see --help)"};
  } catch (const CLI::ArgumentMismatch& error) {
    for (const OptionSpec& option : options_)
      if (!option.valueName.empty() && std::string(error.what()).find("--" + option.name) != std::string::npos)
        return Error{"--" + option.name + " needs a value: --" + option.name + " " + option.valueName};
    return Error{error.what()};
  } catch (const CLI::ParseError& error) {
    return Error{error.what()};
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

std::string CommandLine::help() const { return app_->help(); }

bool CommandLine::has(const std::string& name) const {
  find(name);
  return app_->count("--" + name) > 0;
}

bool CommandLine::declares(const std::string& name) const {
  return std::any_of(options_.begin(), options_.end(), [&](const OptionSpec& option) { return option.name == name; });
}

std::string CommandLine::text(const std::string& name) const {
  const OptionSpec& option = find(name);
  return has(name) ? values_.at(name) : option.defaultValue;
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
