#!/bin/bash
# Searched frames (--ray-cast never) before and after the GPU-driven tessellation rounds, the two
# binaries alternated scene by scene in one sitting on one machine, each timed pass by pass (a
# glFinish after each pass on llvmpipe, as both binaries can); then from the new binary the searched
# and ray-cast frames timed whole, as served (--pass-timing frame): searched ÷ cast. Writes one
# CSV/JSON pair per run next to this script, and summary.csv.
# Usage: run.sh BEFORE_SPECULA AFTER_SPECULA [FRAMES]
set -euo pipefail
before=$1 after=$2 frames=${3:-20}
out=$(dirname "$0")
scenes=${SCENES:-checker-sphere,mesh-sphere,quad,teapot-table,cylinder,kitchen,ufo,beads}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
frame_ms() { python3 -c 'import csv,sys; r=next(csv.DictReader(open(sys.argv[1]))); print(r["frame_ms_median"])' "$1"; }
echo "scene,before_searched_ms,after_searched_ms,searched_frame_ms,cast_frame_ms,searched_over_cast" >"$out/summary.csv"
for scene in ${scenes//,/ }; do
  for which in before after; do
    binary=$before; [[ $which == after ]] && binary=$after
    "$binary" bench --scenes "$scene" --frames "$frames" --no-reference --cold-size none --ray-cast never \
      --csv "$out/$which-$scene-searched.csv" --json "$out/$which-$scene-searched.json" >"$scratch/log" 2>&1 ||
      { cat "$scratch/log" >&2; exit 1; }
  done
  for rule in never always; do
    "$after" bench --scenes "$scene" --frames "$frames" --no-reference --cold-size none --ray-cast $rule --pass-timing frame \
      --csv "$out/frame-$scene-$rule.csv" --json "$out/frame-$scene-$rule.json" >"$scratch/log" 2>&1 || { cat "$scratch/log" >&2; exit 1; }
  done
  searched=$(frame_ms "$out/frame-$scene-never.csv") cast=$(frame_ms "$out/frame-$scene-always.csv")
  echo "$scene,$(frame_ms "$out/before-$scene-searched.csv"),$(frame_ms "$out/after-$scene-searched.csv"),$searched,$cast,$(python3 -c "print(round($searched / $cast, 2))")" |
    tee -a "$out/summary.csv"
done
