#pragma once
// Result files of the benchmarks: checked before the long part, written after it.
#include <string>

#include "base/Result.h"

namespace specula::app {

// Fails (naming the path and the fix) when `path` cannot be written. Opening for append creates a
// missing file but keeps an earlier run's results until the new ones exist.
Status checkWritable(const std::string& path);
Status writeFile(const std::string& path, const std::string& text);

}  // namespace specula::app
