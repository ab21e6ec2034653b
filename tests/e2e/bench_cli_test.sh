#!/usr/bin/env bash
# `specula bench` as a user runs it, kept tiny: a table, CSV and JSON with every column filled where
# it applies, and errors that name the problem before any long work starts.
# usage: bench_cli_test.sh PATH/TO/specula
set -uo pipefail
specula="$1"
source "$(dirname "$0")/checks.sh"

# Every mirror searched (the planner would ray-cast them, cheaper on llvmpipe): the search's columns filled.
output=$("$specula" bench --scenes checker-sphere,kitchen --size 160x120 --frames 3 --cold-size 320x240 --ray-cast never \
  --csv "$work/b.csv" --json "$work/b.json" 2>"$work/progress.txt")
check "bench succeeds on two scenes" test $? -eq 0
check "bench reports progress per scene" grep -q "bench \[2/2\] kitchen: done in" "$work/progress.txt"
check "the table has a row per scene" contains "$output" '^checker-sphere ' '^kitchen '
check "the table lists the passes" grep -q "passes (median ms): scene .* search .* virtual-objects" <<<"$output"
check "the CSV has a header and two rows" test "$(wc -l <"$work/b.csv")" -eq 3
columns=$(head -1 "$work/b.csv" | tr ',' '\n' | wc -l)
check "every CSV row has the header's columns" awk -F, -v n="$columns" 'NF != n { exit 1 }' "$work/b.csv"
for column in frame_ms_median raster_floor_ms search_ms steps_warm_mean steps_cold_large_max point_error_p99_px psnr_db ssim raytrace_ms frame_vs_raytrace; do
  check "the CSV has column $column" grep -q "\(^\|,\)$column\(,\|$\)" <(head -1 "$work/b.csv")
done
# Column values by name, so the checks do not depend on column order.
value() { awk -F, -v scene="$1" -v column="$2" 'NR == 1 { for (i = 1; i <= NF; i++) at[$i] = i } $1 == scene { print $at[column] }' "$work/b.csv"; }
check "the sphere's point error is measured and below 3 px" awk -v e="$(value checker-sphere point_error_p99_px)" 'BEGIN { exit !(e != "" && e >= 0 && e < 3) }'
check "the bowl has no analytic sphere, so no point error" test -z "$(value kitchen point_error_p99_px)"
check "cold searches take more steps than warm ones" awk -v c="$(value checker-sphere steps_cold_mean)" -v w="$(value checker-sphere steps_warm_mean)" 'BEGIN { exit !(c > w && w > 0) }'
check "the raster floor is measured and below the kitchen's reflected frame" awk -v f="$(value kitchen raster_floor_ms)" -v t="$(value kitchen frame_ms_median)" 'BEGIN { exit !(f > 0 && f < t) }'
check "PSNR against the ray tracer is a number up to the 100 dB of identical images" awk -v p="$(value checker-sphere psnr_db)" 'BEGIN { exit !(p > 10 && p <= 100) }'
check "the JSON names both scenes" bash -c "grep -q '\"scene\": \"checker-sphere\"' '$work/b.json' && grep -q '\"scene\": \"kitchen\"' '$work/b.json'"
check "the JSON writes null where nothing was measured" grep -q '"point_error_p99_px": null' "$work/b.json"

"$specula" bench --scenes quad --size 64x48 --frames 1 --cold-size none --no-reference --csv "$work/q.csv" --json "$work/q.json" >/dev/null 2>&1
check "bench succeeds without reference and large cold frame" test $? -eq 0
check "by default the planner ray-casts the quad's small sphere" test "$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) at[$i] = i } NR == 2 { print $at["ray_cast_parts"] }' "$work/q.csv")" = 1
check "that CSV has a header and one row" test "$(wc -l <"$work/q.csv")" -eq 2
check "--no-reference and --cold-size none leave those cells empty" bash -c "[[ -z \"\$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) at[\$i] = i } NR == 2 { print \$at[\"psnr_db\"] \$at[\"steps_cold_large_mean\"] }' '$work/q.csv')\" ]]"

fails_with "an unknown scene fails before rendering" "neither a built-in scene" bench --scenes checker-sphere,nope --csv "$work/x.csv"
fails_with "a bad frame count names the option" "--frames expects an integer" bench --frames 0
fails_with "an unknown GL backend fails before rendering" "--gl expects auto, egl-device" bench --gl glx
fails_with "a bad cold size names the option" "--cold-size expects WIDTHxHEIGHT" bench --cold-size big
fails_with "a bad size in --sizes names the option and the item" "--sizes expects WIDTHxHEIGHT with sides in [1, 4096] like 640x480, got '64x'" bench --sizes 640x480,64x
fails_with "--size and --sizes together are refused" "give --size or --sizes, not both" bench --size 64x64 --sizes 64x64
fails_with "an unknown pass timing names the choices" "--pass-timing expects per-pass or frame, got 'never'" bench --pass-timing never
fails_with "an unwritable CSV names the file" "could not write '$work/no/dir/b.csv'" bench --scenes quad --size 32x24 --frames 1 --csv "$work/no/dir/b.csv"
unwritable=$("$specula" bench --scenes quad --size 32x24 --frames 1 --json "$work/no/dir/b.json" 2>&1)
check "an unwritable JSON fails before any scene is measured" lacks "$unwritable" 'bench \[1/1\]'
check "bench --help lists every option" bash -c "for o in scenes size frames cold-size no-reference csv json gl; do '$specula' bench --help | grep -q -- \"--\$o\" || exit 1; done"
check "specula --help lists bench" bash -c "'$specula' --help | grep -q '^  bench'"

# bench tessellation: one row per setting of the sweep, counts that follow the level rule.
output=$("$specula" bench tessellation --scenes quad --size 160x120 --frames 1 --csv "$work/t.csv" --json "$work/t.json" 2>"$work/tprogress.txt")
check "bench tessellation succeeds" test $? -eq 0
check "bench tessellation reports progress per setting" grep -q "bench tessellation \[1/1\] quad: \[16/16\] crack-free pixels >= 0.1 level 5" "$work/tprogress.txt"
check "its CSV has a header and the 16 settings" test "$(wc -l <"$work/t.csv")" -eq 17
tcolumns=$(head -1 "$work/t.csv" | tr ',' '\n' | wc -l)
check "every tessellation CSV row has the header's columns" awk -F, -v n="$tcolumns" 'NF != n { exit 1 }' "$work/t.csv"
tvalue() { awk -F, -v setting="$1" -v column="$2" 'NR == 1 { for (i = 1; i <= NF; i++) at[$i] = i } $2 == setting { print $at[column] }' "$work/t.csv"; }
check "untessellated, the quad's 2 triangles are drawn" test "$(tvalue none triangles)" = 2
check "full level 3 draws 2 x 4^3 triangles" test "$(tvalue 'crack-free angle >= 0 level 3' triangles)" = 128
check "full level 5 is more accurate than none" awk -v a="$(tvalue 'crack-free angle >= 0 level 5' mirror_mismatch)" -v b="$(tvalue none mirror_mismatch)" 'BEGIN { exit !(a < b) }'
check "the summary names the goal" grep -q "^quad: " <<<"$output"
check "the tessellation JSON lists the settings" grep -q '"setting": "crack-free pixels >= 1 level 5"' "$work/t.json"
check "bench tessellation --help tells what it sweeps" bash -c "'$specula' bench tessellation --help | grep -q 'full tessellation at levels 1-5'"
fails_with "bench tessellation checks its options" "--frames expects an integer" bench tessellation --frames 0
fails_with "bench tessellation names a bad time" "--time expects a finite number, got 'soon'" bench tessellation --time soon
fails_with "bench tessellation checks its outputs before work" "could not write '$work/no/dir/t.csv'" bench tessellation --scenes quad --csv "$work/no/dir/t.csv"

# bench accuracy: every setting of the sweep plus the reference, in every format, with a real plot.
output=$("$specula" bench accuracy --scene quad --size 128x96 --poses 2 --out "$work/acc" 2>"$work/aprogress.txt")
check "bench accuracy succeeds" test $? -eq 0
check "bench accuracy reports progress per reference pose and setting" bash -c \
  "grep -q 'bench accuracy quad \[1/28\] ray-traced reference, pose 1/2' '$work/aprogress.txt' && grep -q '\[28/28\] ray-cast every mirror' '$work/aprogress.txt'"
check "its CSV has a header, the reference and 26 settings" test "$(wc -l <"$work/acc/accuracy.csv")" -eq 28
check "both searches are side by side" grep -q "^quad,hierarchy search,hierarchy," "$work/acc/accuracy.csv"
acolumns=$(head -1 "$work/acc/accuracy.csv" | tr ',' '\n' | wc -l)
check "every accuracy CSV row has the header's columns (names with commas quoted)" \
  bash -c "sed 's/\"[^\"]*\"/name/g' '$work/acc/accuracy.csv' | awk -F, -v n=$acolumns 'NF != n { exit 1 }'"
avalue() { sed 's/"[^"]*"/quoted/g' "$work/acc/accuracy.csv" | awk -F, -v setting="$1" -v column="$2" \
  'NR == 1 { for (i = 1; i <= NF; i++) at[$i] = i } $2 == setting { print $at[column] }'; }
check "full level 4 is closer to the reference than the environment map" \
  awk -v a="$(avalue 'full level 4' mirror_mismatch)" -v b="$(avalue 'environment map 256 px' mirror_mismatch)" 'BEGIN { exit !(a < b) }'
check "the quad's analytic sphere gets a reflection-point error" awk -v e="$(avalue 'full level 4' point_error_p99_px)" 'BEGIN { exit !(e != "" && e < 1) }'
check "ray-casting every mirror matches the ray tracer" awk -v m="$(avalue 'ray-cast every mirror' mirror_mismatch)" 'BEGIN { exit !(m != "" && m < 0.005) }'
check "... and searches nothing, so has no reflection points" test -z "$(avalue 'ray-cast every mirror' point_error_p99_px)"
check "the environment map has no reflection points to measure" test -z "$(avalue 'environment map 256 px' point_error_p99_px)"
check "the live estimate sits beside the full comparison and tracks it" awk -v e="$(avalue 'environment map 256 px' estimate_mean)" \
  -v m="$(avalue 'environment map 256 px' mirror_mismatch)" 'BEGIN { exit !(m > 0.05 && e > m - 0.05 && e < m + 0.05) }'
check "... with its interval's coverage and cost on every setting" bash -c \
  "sed 's/\"[^\"]*\"/quoted/g' '$work/acc/accuracy.csv' | awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) at[\$i] = i } NR > 2 && (\$at[\"estimate_coverage\"] == \"\" || \$at[\"estimate_ms\"] <= 0) { exit 1 }'"
check "some setting is on the Pareto front" grep -q ',true$' "$work/acc/accuracy.csv"
check "the reference is never on it" grep -q '^quad,ray-traced reference,reference,.*,false$' "$work/acc/accuracy.csv"
check "the Markdown table is printed" contains "$output" '^| ray-traced reference |'
check "... and written" grep -q '^| setting | frame ms |' "$work/acc/accuracy.md"
check "the JSON lists the settings" grep -q '"setting": "adaptive 0.5 px"' "$work/acc/accuracy.json"
check "the PNG is a PNG" bash -c "head -c 8 '$work/acc/accuracy.png' | od -An -tx1 | grep -q '89 50 4e 47 0d 0a 1a 0a'"
check "the SVG is an SVG with the Pareto front" bash -c "grep -q '<svg' '$work/acc/accuracy.svg' && grep -q 'Pareto front' '$work/acc/accuracy.svg'"
check "the gnuplot script redraws the plot" bash -c "cd '$work/acc' && rm accuracy.png && gnuplot accuracy.gp && test -s accuracy.png"
nognuplot=$(PATH=/nonexistent "$specula" bench accuracy --scene quad --out "$work/acc2" 2>&1)
check "without gnuplot bench accuracy fails" test $? -ne 0
check "... naming the package and --no-plot" contains "$nognuplot" 'apt-get install gnuplot-nox' '--no-plot'
check "without gnuplot it fails before rendering" lacks "$nognuplot" 'bench accuracy quad'
PATH=/nonexistent "$specula" bench accuracy --scene quad --size 64x48 --poses 1 --no-plot --out "$work/acc4" >/dev/null 2>&1
check "--no-plot works without gnuplot and still writes the script" bash -c "test -s '$work/acc4/accuracy.csv' && test -s '$work/acc4/accuracy.gp' && test ! -e '$work/acc4/accuracy.png'"
fails_with "bench accuracy names a bad orbit" "--orbit expects degrees from 0 to 180" bench accuracy --orbit 500
fails_with "bench accuracy names bad scene seconds" "--seconds expects scene seconds from 0 to 3600, got 'later'" bench accuracy --seconds later
fails_with "bench accuracy names a bad size" "--size expects WIDTHxHEIGHT" bench accuracy --size huge
fails_with "bench accuracy names a bad pose count" "--poses expects an integer" bench accuracy --poses 0
fails_with "bench accuracy names an unknown scene" "neither a built-in scene" bench accuracy --scene nope --out "$work/acc5"
fails_with "bench accuracy names an output folder it cannot create" "could not create the output folder" bench accuracy --out /proc/nope
check "bench accuracy --help tells what it sweeps and writes" bash -c "'$specula' bench accuracy --help | grep -q 'environment-map' && '$specula' bench accuracy --help | grep -q 'Pareto front'"
finish
