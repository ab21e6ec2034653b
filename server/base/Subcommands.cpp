#include "base/Subcommands.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>

namespace specula {

namespace {

// "usage: specula <command> [options]", the summary, then CLI11's list of subcommands.
class SubcommandHelp : public CLI::Formatter {
 public:
  explicit SubcommandHelp(std::string usage) : usage_(std::move(usage)) { column_width(14); }
  std::string make_description(const CLI::App*) const override { return ""; }
  std::string make_usage(const CLI::App* app, std::string) const override {
    return "usage: " + usage_ + "\n\n" + app->get_description() + "\n";
  }
  std::string make_footer(const CLI::App* app) const override {
    return "\nRun `" + app->get_name() + " <command> --help` for a command's options.\n";
  }

 private:
  std::string usage_;
};

}  // namespace

int runSubcommand(const std::string& program, const std::string& summary, const std::vector<Subcommand>& subcommands,
                  std::span<const std::string> arguments,
                  const std::function<int(std::span<const std::string>)>& fallback) {
  CLI::App app(summary, program);
  app.formatter(std::make_shared<SubcommandHelp>(program + " <command> [options]"));
  app.set_help_flag("-h,--help", "print this help");
  app.require_subcommand(0, 1);
  const Subcommand* chosen = nullptr;
  for (const Subcommand& subcommand : subcommands) {
    CLI::App* added = app.add_subcommand(subcommand.name, subcommand.summary);
    added->prefix_command();  // the rest is the subcommand's, --help included
    added->set_help_flag();
    added->parse_complete_callback([&chosen, &subcommand] { chosen = &subcommand; });
  }
  const bool namesOne =
      !arguments.empty() && std::any_of(subcommands.begin(), subcommands.end(),
                                        [&](const Subcommand& s) { return s.name == arguments.front(); });
  if (fallback && !namesOne) return fallback(arguments);
  std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());  // CLI11 takes them last first
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::ParseError&) {
    std::cerr << program << ": unknown command '" << arguments.front() << "'\n\n" << app.help();
    return 2;
  }
  if (!chosen) {
    std::cerr << app.help();
    return 2;
  }
  const CLI::App& used = *app.get_subcommand(chosen->name);
  const std::vector<std::string> rest = used.remaining();
  return chosen->run(rest);
}

}  // namespace specula
