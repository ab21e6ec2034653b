// Runs every file under the folders named on the command line once through LLVMFuzzerTestOneInput: a
// fuzz target's seed corpus and regression inputs, in the normal (GCC, sanitized) build, without libFuzzer.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::vector<fs::path> inputs;
  for (int i = 1; i < argc; ++i) {
    if (!fs::is_directory(argv[i])) {
      std::fprintf(stderr, "%s: %s is not a folder of inputs\n", argv[0], argv[i]);
      return 2;
    }
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(argv[i]))
      if (entry.is_regular_file()) inputs.push_back(entry.path());
  }
  for (const fs::path& input : inputs) {
    std::ifstream file(input, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(file), {}};
    std::fprintf(stderr, "%s\n", input.c_str());  // a sanitizer report follows the input that caused it
    // A copy of exactly `size` bytes, so a read past the end is a heap overflow the sanitizer sees.
    const std::vector<std::uint8_t> copy(bytes.begin(), bytes.end());
    const auto start = std::chrono::steady_clock::now();
    LLVMFuzzerTestOneInput(copy.data(), copy.size());
    // A hang is a finding too: libFuzzer's limit (run_fuzzers.sh -timeout=25), for inputs that take milliseconds.
    if (std::chrono::steady_clock::now() - start > std::chrono::seconds(25)) {
      std::fprintf(stderr, "%s ran longer than 25 s: a hang\n", input.c_str());
      return 1;
    }
  }
  std::printf("%zu inputs ran without a finding\n", inputs.size());
  return 0;
}
