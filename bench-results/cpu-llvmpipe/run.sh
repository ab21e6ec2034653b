#!/bin/bash
# The CPU tables of docs/benchmarks.md and docs/serving.md, from one session on a quiet machine (software GL, llvmpipe):
# `specula bench` at default settings, searched (--ray-cast never) and with the planner off
# (--plan everything), `specula bench serve` alone and behind HAProxy, and perf profiles of the
# frame loop. Writes CSV/JSON, logs and profiles next to this script; docs/tools/bench_tables.py writes the tables.
# Usage: bench-results/cpu-llvmpipe/run.sh [BUILD_DIR [STEP...]]
#   steps: default searched everything serve instances profiles (default: all; about an hour on 2 cores)
set -euo pipefail
build=${1:-build}
shift || true
steps=${*:-default searched everything serve instances profiles}
out=$(dirname "$0")
specula="$build/bin/specula"
[[ -x $specula ]] || { echo "run.sh: $specula not found; build first: cmake -S . -B $build -G Ninja && cmake --build $build" >&2; exit 2; }
scenes=checker-sphere,mesh-sphere,cylinder,kitchen,ufo,ants,quad,teapot-table,beads,utah-teapot,tests/data/gltf/engine.glb
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
step() { echo "run.sh: $1 ($(date +%T)) ..." >&2; }
timed() { local log=$1; shift; /usr/bin/time -f "%e s wall" -o "$log.time" "$@" >"$log" 2>&1; }
wants() { [[ " $steps " == *" $1 "* ]]; }
if wants default; then
  step "bench, default settings"
  timed "$out/bench.log" "$specula" bench --scenes "$scenes" --csv "$out/bench.csv" --json "$out/bench.json"
fi
if wants searched; then
  step "bench --ray-cast never"
  timed "$out/bench-searched.log" "$specula" bench --scenes "$scenes" --ray-cast never --cold-size none \
    --csv "$out/bench-searched.csv" --json "$out/bench-searched.json"
fi
if wants everything; then
  # 20 frames and no reference: the planner off searches every mirror, as slowly as the run above;
  # docs/tools/bench_tables.py sets its frames against the default run's ray tracer.
  step "bench --plan everything"
  timed "$out/bench-everything.log" "$specula" bench --scenes "$scenes" --plan everything --cold-size none --frames 20 \
    --no-reference --csv "$out/bench-everything.csv" --json "$out/bench-everything.json"
fi
if wants serve; then
  step "bench serve"
  timed "$out/serve.log" "$specula" bench serve --csv "$out/serve.csv" --json "$out/serve.json"
fi
if wants instances && command -v haproxy >/dev/null; then
  step "bench serve --instances 3"
  timed "$out/serve-instances.log" "$specula" bench serve --instances 3 --sessions 3,6,12 --sizes 640x360 --seconds 5 \
    --csv "$out/serve-instances.csv" --json "$out/serve-instances.json"
fi
if wants profiles && command -v perf >/dev/null; then
  # Where the time goes inside the process, by shared object and by thread: llvmpipe's JIT-compiled
  # shaders (no symbols: "[JIT]", the memory they run from), its rasterizer (swrast_dri.so), the rest;
  # without the ray-traced reference, so that the profile is the rasterized frames alone.
  profiled=${PROFILE_SCENES:-checker-sphere,ufo,tests/data/gltf/engine.glb}
  for scene in ${profiled//,/ }; do
    name=$(basename "${scene%.glb}")
    step "perf profile of $name"
    perf record -q -F 499 -o "$scratch/perf.data" -- "$specula" bench --scenes "$scene" --frames 20 --cold-size none --no-reference \
      --csv "$scratch/perf.csv" --json "$scratch/perf.json" >"$out/perf-$name.log" 2>&1
    perf report -q -i "$scratch/perf.data" --no-children --sort dso --percent-limit 1 --stdio >"$out/perf-$name-dso.txt" 2>/dev/null
    perf report -q -i "$scratch/perf.data" --no-children --sort comm,dso --percent-limit 1 --stdio >"$out/perf-$name-threads.txt" 2>/dev/null
  done
fi
echo "run.sh: wrote $out/ ($(date +%T))" >&2
