#!/bin/bash
# The wave-3 figures of docs/benchmarks.md on llvmpipe: five built-in scenes at 640x480 and 1920x1080, each
# with the planner's default frames, every part searched and every part cast (searched / cast),
# and the planner's last measured prediction. About 10 minutes on 2 cores.
# Usage: bench-results/cpu-llvmpipe-wave3/run.sh [BUILD_DIR]
set -euo pipefail
build=${1:-build}
out=$(dirname "$0")
"$build/bin/specula" bench --scenes checker-sphere,mesh-sphere,quad,teapot-table,kitchen --sizes 640x480,1920x1080 --frames 10 \
  --no-reference --cold-size none --csv "$out/bench-sizes.csv" --json "$out/bench-sizes.json" >"$out/bench-sizes.log" 2>&1
