#pragma once
// How every Specula program reports the error that stops it: "<program>: <message>" on stderr.
#include <iostream>
#include <string>
#include <string_view>

namespace specula {

// `return fail(message);` in a command: prints the message after the program's name and gives the exit
// code 1. Callable as CommandLine::parseOrExit's `fail`.
class CommandFailure {
 public:
  constexpr explicit CommandFailure(std::string_view program) : program_(program) {}

  int operator()(const std::string& message) const {
    std::cerr << program_ << ": " << message << "\n";
    return 1;
  }

 private:
  std::string_view program_;
};

}  // namespace specula
