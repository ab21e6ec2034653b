#!/usr/bin/env bash
# The live accuracy estimate, measured: (1) an accuracy target of 0.5 % along a path that approaches
# checker-sphere's mirror from far away; (2) what estimating costs a loaded server (4 sessions at 640x360,
# accuracy-samples 256 against 0, alternating); (3) `bench accuracy` on checker-sphere and the kitchen,
# where the estimate stands beside the full comparison for every setting.
# usage: bench-results/live-accuracy/run.sh [PATH/TO/bin]   (default build/bin); writes beside itself.
set -euo pipefail
bin="${1:-build/bin}"
out="$(cd "$(dirname "$0")" && pwd)"
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; rm -rf "$work"' EXIT

serve() {  # serve ARGS...: starts `specula serve` on a free port, sets $port
  "$bin/specula" serve --port 0 "$@" >"$work/serve.log" 2>&1 &
  for _ in $(seq 600); do grep -q "listening on" "$work/serve.log" && break; sleep 0.1; done
  port=$(sed -n 's/.*listening on 127\.0\.0\.1:\([0-9]*\).*/\1/p' "$work/serve.log")
}

cat >"$work/approach.json" <<'JSON'
{"keys": [{"time": 0, "eye": [12, 36, 42], "target": [0, -0.3, 0], "fov": 40, "scene_time": 0},
          {"time": 6, "eye": [1.0, 3.0, 3.5], "target": [0, -0.3, 0], "fov": 40, "scene_time": 0}]}
JSON
serve --scene checker-sphere --accuracy-target 0.5
"$bin/specula-path" --url "ws://127.0.0.1:$port" --path "$work/approach.json" --fps 15 --size 320x240 \
  --csv "$out/approach-target-0.5.csv" 2>/dev/null | tee "$out/approach-target-0.5.txt"
kill %1; wait %1 2>/dev/null || true

for round in 1 2; do
  for samples in 256 0; do
    serve --scene checker-sphere --accuracy-samples "$samples"
    "$bin/specula-load" --url "ws://127.0.0.1:$port" --sessions 4 --seconds 6 --warmup 2 --size 640x360 \
      --json "$out/load-samples-$samples-round-$round.json" 2>/dev/null >"$out/load-samples-$samples-round-$round.txt"
    kill %1; wait %1 2>/dev/null || true
  done
done

for scene in checker-sphere kitchen; do
  "$bin/specula" bench accuracy --scene "$scene" --size 320x240 --poses 4 --no-plot --out "$out/accuracy-$scene" \
    2>/dev/null >/dev/null
done
