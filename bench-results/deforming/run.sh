#!/usr/bin/env bash
# Deforming geometry in the bench (issue #40): the built-in flag and the generated morphing, skinned and
# deforming-mirror glTF files, searched and ray-cast, then each one's accuracy over its 2 s animation.
# Run from this folder after building: ./run.sh [path/to/specula]  (about 6 minutes on 2 cores, llvmpipe)
set -euo pipefail
specula="${1:-../../build/bin/specula}"
data=../../tests/data/gltf
scenes="flag,$data/morphing.glb,$data/skinned.glb,$data/deforming-mirrors.glb"
for rule in never always; do
  "$specula" bench --scenes "$scenes" --frames 30 --ray-cast "$rule" \
    --csv "bench-$rule.csv" --json "bench-$rule.json" > "bench-$rule.txt" 2>&1
done
for scene in flag morphing skinned deforming-mirrors; do
  file="$scene"
  [[ "$scene" == flag ]] || file="$data/$scene.glb"
  "$specula" bench accuracy --scene "$file" --seconds 2 --orbit 0 --poses 8 --out "accuracy-$scene" \
    > "accuracy-$scene.txt" 2>&1
done
