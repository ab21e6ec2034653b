#pragma once
// Options of one subcommand: `--name value`, `--name=value` or a bare `--flag`, parsed by CLI11. The
// same table parses the arguments and prints --help, so the help cannot drift from what is accepted.
#include <glm/glm.hpp>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "base/Result.h"

namespace CLI {
class App;
}

namespace specula {

struct OptionSpec {
  std::string name;       // without dashes: "size"
  std::string valueName;  // "WxH"; empty for a flag that takes no value
  std::string help;
  std::string defaultValue;  // shown in --help; empty for none
};

class CommandLine {
 public:
  CommandLine(std::string usage, std::string summary, std::vector<OptionSpec> options);
  CommandLine(CommandLine&&) noexcept;
  CommandLine& operator=(CommandLine&&) noexcept;
  ~CommandLine();

  // Parses arguments after the subcommand. --help sets helpRequested() instead of failing.
  Status parse(std::span<const std::string> arguments);
  // parse() as every command starts: after --help (printed to stdout) returns 0; after an error
  // returns fail(error); else nullopt, and the command goes on.
  std::optional<int> parseOrExit(std::span<const std::string> arguments,
                                 const std::function<int(const std::string&)>& fail);
  bool helpRequested() const { return helpRequested_; }
  std::string help() const;

  // Whether the arguments gave the option (a flag: whether it was set).
  bool has(const std::string& name) const;
  // Whether the table declares the option.
  bool declares(const std::string& name) const;
  // The given value, else the option's default. Asking for an option the table does not declare is
  // a programming error: it throws std::logic_error.
  std::string text(const std::string& name) const;

  // Typed readers; each error names the option, what it expects and what it got.
  Result<double> number(const std::string& name) const;
  Result<int> integer(const std::string& name, int low, int high) const;
  Result<glm::vec3> vector3(const std::string& name) const;
  Result<std::pair<int, int>> size(const std::string& name, int maxSide) const;
  // Comma-separated lists of the same ("1,4,16", "640x360,1280x720").
  Result<std::vector<int>> integerList(const std::string& name, int low, int high) const;
  Result<std::vector<std::pair<int, int>>> sizeList(const std::string& name, int maxSide) const;

 private:
  const OptionSpec& find(const std::string& name) const;

  std::vector<OptionSpec> options_;
  std::unique_ptr<CLI::App> app_;
  std::map<std::string, std::string> values_;  // every declared option's storage; given ones are has()
  bool helpRequested_ = false;
};

}  // namespace specula
