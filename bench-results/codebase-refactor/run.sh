#!/usr/bin/env bash
# Issue #38's behaviour check: the bench before the restructuring (commit 0d872a1) and after it, on
# the same machine in one sitting, alternating binaries. Each CSV holds time per pass and the accuracy
# against the ray tracer (mismatch, PSNR, reflection-point error); compare.py prints them side by side.
# usage: run.sh OLD/bin/specula NEW/bin/specula [OUT-DIR]
set -euo pipefail
old="$1" new="$2" out="${3:-$(dirname "$0")}"
scenes=quad,checker-sphere,mesh-sphere,teapot-table,kitchen
for round in 1 2; do
  for which in old new; do
    binary=$old; [[ $which == new ]] && binary=$new
    "$binary" bench --scenes "$scenes" --size 320x240 --frames 8 --ray-cast never \
      --csv "$out/bench-$which-$round.csv" --json "$out/bench-$which-$round.json" >"$out/bench-$which-$round.log" 2>&1
  done
done
python3 "$(dirname "$0")/compare.py" "$out"
