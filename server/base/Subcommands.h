#pragma once
// A program's subcommands (`specula render …`, `specula bench accuracy …`), dispatched by CLI11: the
// first argument names one, which parses the rest with its own CommandLine; --help lists them.
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace specula {

struct Subcommand {
  std::string name;
  std::string summary;  // one line, for the list --help prints
  std::function<int(std::span<const std::string>)> run;
};

// Runs the subcommand the first argument names with the arguments after it and returns its exit code.
// When it names none, `fallback` (if given) gets every argument (`specula bench --scenes quad`);
// otherwise --help prints the list (exit 0), nothing prints it to stderr (exit 2), and an unknown
// name is refused (exit 2).
int runSubcommand(const std::string& program, const std::string& summary, const std::vector<Subcommand>& subcommands,
                  std::span<const std::string> arguments,
                  const std::function<int(std::span<const std::string>)>& fallback = {});

}  // namespace specula
