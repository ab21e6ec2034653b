#include "app/Plotting.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace specula::app {

bool gnuplotAvailable() {
  const char* path = std::getenv("PATH");
  std::stringstream folders(path ? path : "/usr/bin:/bin");
  for (std::string folder; std::getline(folders, folder, ':');)
    if (!folder.empty() && access((folder + "/gnuplot").c_str(), X_OK) == 0) return true;
  return false;
}

Status runGnuplot(const std::string& folder, const std::string& scriptFile) {
  const pid_t child = fork();
  if (child < 0) return Error{std::string("could not start gnuplot: ") + std::strerror(errno)};
  if (child == 0) {
    if (chdir(folder.c_str()) != 0) _exit(126);
    execlp("gnuplot", "gnuplot", scriptFile.c_str(), static_cast<char*>(nullptr));
    _exit(127);  // exec failed: gnuplot is not on PATH
  }
  int status = 0;
  while (waitpid(child, &status, 0) < 0)
    if (errno != EINTR) return Error{std::string("waiting for gnuplot: ") + std::strerror(errno)};
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
    return Error{std::string("gnuplot was not found: ") + kInstallGnuplot};
  if (WIFEXITED(status) && WEXITSTATUS(status) == 126) return Error{"could not enter '" + folder + "' to run gnuplot"};
  return Error{"gnuplot failed on " + folder + "/" + scriptFile + " (exit status " +
               std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status)) + ")"};
}

}  // namespace specula::app
