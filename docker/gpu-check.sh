#!/bin/bash
# The GPU check: GL tests on the GPU, then `specula bench` (default and searched) and
# `specula bench serve`, all with --gl egl-device, writing CSV/JSON and logs to one folder.
# Usage: docker/gpu-check.sh [BUILD_DIR [OUT_DIR]]   (defaults: build, gpu-check)
# GL=egl-surfaceless docker/gpu-check.sh tries the same on software GL (slow: minutes per bench).
set -euo pipefail
build=${1:-build}
out=${2:-gpu-check}
gl=${GL:-egl-device}
specula="$build/bin/specula"
tests="$build/tests/specula_gl_tests"
for binary in "$specula" "$tests"; do
  [[ -x $binary ]] || { echo "gpu-check: $binary not found; build first: cmake -S . -B $build -G Ninja && cmake --build $build" >&2; exit 2; }
done
mkdir -p "$out"
if ! "$specula" render --gl "$gl" --scene quad --out "$out/quad.png" >"$out/render.log" 2>&1; then
  echo "gpu-check: no GL context on --gl $gl:" >&2
  cat "$out/render.log" >&2
  exit 1
fi
head -1 "$out/render.log"
step() { echo "gpu-check: $1 ..." >&2; }
# The Software/* suites test Mesa's platforms, which a GPU machine need not have; the rest runs on
# whatever --gl auto picks, the GPU first.
step "GL tests"
"$tests" --gtest_filter=-Software/* --gtest_output="xml:$out/gl-tests.xml" >"$out/gl-tests.log" 2>&1 || gl_failed=1
grep -E '^\[  (PASSED|FAILED) ' "$out/gl-tests.log" >&2 || true
step "bench (default settings, with the ray-traced reference)"
"$specula" bench --gl "$gl" --csv "$out/bench.csv" --json "$out/bench.json" >"$out/bench.log" 2>&1
step "bench --ray-cast never (every mirror searched)"
"$specula" bench --gl "$gl" --ray-cast never --no-reference --cold-size none --frames 20 \
  --csv "$out/bench-searched.csv" --json "$out/bench-searched.json" >"$out/bench-searched.log" 2>&1
step "bench serve"
"$specula" bench serve --gl "$gl" --sessions 1,4,16 --sizes 640x360,1280x720 --seconds 3 \
  --csv "$out/serve.csv" --json "$out/serve.json" >"$out/serve.log" 2>&1
echo "gpu-check: wrote $out/ (gl-tests.xml, bench*.csv/json, serve.csv/json, logs)" >&2
[[ -z ${gl_failed:-} ]] || { echo "gpu-check: GL tests failed, see $out/gl-tests.log" >&2; exit 1; }
