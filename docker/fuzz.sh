#!/usr/bin/env bash
# Fuzzes every parser that reads outside input (tests/fuzz) for as long as asked, keeping each target's
# growing corpus in build/fuzz/corpus/ between runs. Prints per target executions per second, total
# executions and coverage edges; crashes, leaks and hangs are saved as build/fuzz/findings/<target>/
# crash-<sha1> (leak-, timeout-, oom-): add them to tests/fuzz/regressions/<target>/ once fixed.
# usage: docker/fuzz.sh SECONDS_PER_TARGET [TARGET...]   (FUZZ_RUNS=N: also stop each after N executions)
set -euo pipefail
(( $# >= 1 )) || { echo "usage: $0 SECONDS_PER_TARGET [TARGET...]" >&2; exit 2; }
cd "$(dirname "$0")/.."
exec tests/fuzz/run_fuzzers.sh build/fuzz "$@"
