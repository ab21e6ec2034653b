#!/usr/bin/env bash
# `specula render` as a user runs it: files written, errors that name the problem, truthful --help.
# usage: render_cli_test.sh PATH/TO/specula
set -uo pipefail
specula="$1"
source "$(dirname "$0")/checks.sh"
is_png() { [[ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" == "89504e470d0a1a0a" ]]; }
is_jpeg() { [[ "$(head -c 3 "$1" | od -An -tx1 | tr -d ' \n')" == "ffd8ff" ]]; }

check "render writes a PNG" "$specula" render --scene checker-sphere --size 160x120 --out "$work/f.png"
check "the PNG has a PNG signature" is_png "$work/f.png"
check "render writes a JPEG" "$specula" render --scene checker-sphere --size 160x120 --out "$work/f.jpg" --gl osmesa
check "the JPEG has a JPEG signature" is_jpeg "$work/f.jpg"
output=$("$specula" render --scene checker-sphere --size 160x120 --method environment-map --verify --out "$work/v.png" 2>&1)
check "render --verify compares the frame with the ray tracer and states the live estimate beside it" \
  bash -c "grep -qE '^verify: against the ray tracer \(4 rays a pixel, .* ms\): PSNR [0-9.]+ dB, SSIM [0-9.]+, mirror pixels wrong [0-9.]+ %; the live estimate from [0-9]+ of them: [0-9.]+ % \(95 %: [0-9.]+ to [0-9.]+ %\)' <<<\"\$0\"" "$output"
check "... whose interval holds the full comparison's share" awk -v line="$(grep '^verify:' <<<"$output")" 'BEGIN {
  match(line, /wrong [0-9.]+ %/); full = substr(line, RSTART + 6, RLENGTH - 8) + 0
  match(line, /95 %: [0-9.]+ to [0-9.]+ %/); split(substr(line, RSTART + 6, RLENGTH - 8), b, " to ")
  exit !(full > 5 && b[1] + 0 <= full && full <= b[2] + 0) }'
output=$("$specula" render --scene checker-sphere --size 64x48 --time 2 --eye 0,4,6 --target 0,0,0 --out "$work/g.png" 2>&1)
check "render prints per-stage timings, anti-aliased by default" grep -q "frame 64x48, 4 samples a pixel, pass times summed over them: scene .* ms, anti-aliasing .* ms, readback .* ms, total .* ms" <<<"$output"
check "render logs the GL platform and renderer" grep -q "specula: GL platform egl-surfaceless" <<<"$output"
output=$("$specula" render --scene checker-sphere --size 64x48 --samples 1 --out "$work/g1.png" 2>&1)
check "--samples 1 renders each pass once, not anti-aliased" grep -q "frame 64x48: scene .* ms, readback .* ms, total .* ms" <<<"$output"
output=$("$specula" render --scene checker-sphere --size 64x48 --samples 8 --method raytrace --out "$work/r8.png" 2>&1)
check "the ray tracer takes the same samples" grep -q "raytrace .* ms (CPU, Embree, 8 rays a pixel)" <<<"$output"
fails_with "a sample count that has no pattern is refused" "--samples: samples per pixel must be 1, 2, 4, 8 or 16, got 3" render --samples 3
fails_with "a sample count out of range is refused" "--samples expects an integer in [1, 16]" render --samples 64
check "every built-in scene renders" bash -c "for s in \$('$specula' scenes | awk '{print \$1}'); do '$specula' render --scene \$s --size 96x72 --out '$work/'\$s.png >/dev/null || exit 1; done"

fails_with "an unknown scene lists the built-ins" "neither a built-in scene (checker-sphere" render --scene no-such-scene
fails_with "a bad size names the option" "--size expects WIDTHxHEIGHT" render --size 640by480
fails_with "a bad vector names the option" "--eye expects three comma-separated numbers" render --eye 1,2
fails_with "a missing environment image is named with the choices" \
  "--environment: 'no-such-sky.jpg' is neither sky, none nor an image this build reads: no-such-sky.jpg" \
  render --environment no-such-sky.jpg
animated="$(dirname "$0")/../data/gltf/animated.glb"
for t in 0.3 1.3; do
  for choice in all none; do
    "$specula" render --scene "$animated" --animation $choice --time $t --size 96x72 --samples 1 --out "$work/animated-$choice-$t.png" >/dev/null 2>&1
  done
done
check "a glTF file's animations play by --time" bash -c "! cmp -s '$work/animated-all-0.3.png' '$work/animated-all-1.3.png'"
check "--animation none holds the rest pose at every time" cmp -s "$work/animated-none-0.3.png" "$work/animated-none-1.3.png"
fails_with "an unknown animation lists the file's" \
  'there is no animation "walk" (the file has 0 "show", 1 "dolly"); name one, or all or none, with --animation' \
  render --scene "$animated" --animation walk
output=$("$specula" render --scene "$(dirname "$0")/../data/gltf/open-chrome.glb" --ray-cast never --size 96x72 --samples 1 --out "$work/open.png" 2>&1)
check "an open chrome mesh is a two-sided mirror, ray-cast with --ray-cast never too" contains "$output" "'bowl' is an open mesh: a two-sided mirror whose reflections are ray-cast" \
  "plan: mirror 'bowl' part 0 (saddle, .*): ray-cast (an open mesh: only a closed one is searched) "
check "a Radiance .hdr image is an environment" "$specula" render --environment "$(dirname "$0")/../data/scenes/good/assets/sky.hdr" --size 96x72 --samples 1 --out "$work/hdr.png"
fails_with "eye on target is refused" "bad camera: camera eye and target coincide" render --eye 0,0,0 --target 0,0,0
fails_with "an unknown output format is refused" "--out must end in .png, .jpg or .jpeg" render --out "$work/f.bmp"
fails_with "an unknown option is refused" "unknown option --colour" render --colour red
fails_with "an unknown GL backend is refused" "--gl expects auto, egl-device" render --gl glx
fails_with "an unknown GL backend is refused for the ray tracer too" "--gl expects auto, egl-device" render --method raytrace --gl glx
fails_with "an unwritable output names the file" "could not write '$work/missing/dir/f.png'" render --size 8x8 --out "$work/missing/dir/f.png"
output=$("$specula" render --scene quad --size 160x120 --ray-cast never --tessellation crack-free --threshold 0 --level 2 --out "$work/q.png" 2>&1)
check "render prints the tessellation it did" grep -q "tessellation: 2 -> 32 triangles; working per round 2 8 32" <<<"$output"
output=$("$specula" render --scene quad --size 160x120 --tessellation none --out "$work/q0.png" 2>&1)
check "--tessellation none runs no tessellation pass" lacks "$output" tessellation
fails_with "a bad tessellation mode lists the modes" "--tessellation expects none, paper or crack-free" render --tessellation fine
fails_with "a bad metric lists the metrics" "--metric expects pixels or angle" render --metric px
fails_with "a negative threshold is refused" "--threshold expects a number in [0, 10000]" render --threshold -1
fails_with "a level past the bound is refused" "--level expects an integer in [0, 8]" render --level 9
fails_with "an unknown method lists the methods" "--method expects search, explosion-map, environment-map, raytrace or none" render --method cubemap
output=$("$specula" render --scene mesh-sphere --size 160x120 --method explosion-map --ray-cast never --out "$work/em.png" 2>&1)
check "--method explosion-map draws the maps and looks them up" contains "$output" 'explosion-map .* ms, search' \
  '(explosion-map), steps mean 1.9' 'explosion map 256x256: steps are map look-ups'
output=$("$specula" render --scene mesh-sphere --size 160x120 --search explosion-map --explosion-refine on --explosion-map-size 64 --ray-cast never --out "$work/emr.png" 2>&1)
check "--explosion-refine on climbs from the map's point, with the pyramid for cold starts" contains "$output" \
  'explosion-map .* ms, gbuffer-pyramid' 'explosion map 64x64, refined'
fails_with "--method explosion-map refuses another search" "--method explosion-map places vertices by the maps; it cannot take --search hierarchy" render --method explosion-map --search hierarchy
fails_with "a map size past the bound is refused" "--explosion-map-size" render --explosion-map-size 8
fails_with "an unknown placement is refused" "--explosion-placement expects eye-ray or mirror, got 'plane'" render --explosion-placement plane
output=$("$specula" render --scene cylinder --size 160x120 --ray-cast never --out "$work/cyl.png" 2>&1)
check "a declared extrusion is solved in 2-D: no pyramid" lacks "$output" gbuffer-pyramid
check "... and no steps" contains "$output" 'steps mean 0.00 max 0' 'extrusion mirrors (1) solved by the 2-D reduction'
output=$("$specula" render --scene cylinder --size 160x120 --ray-cast never --extrusions search --out "$work/cyls.png" 2>&1)
check "--extrusions search searches the cylinder's mesh" contains "$output" gbuffer-pyramid 'extrusion mirrors (1) searched'
fails_with "unknown extrusion handling is refused" "--extrusions expects solve or search, got 'exact'" render --extrusions exact
fails_with "unknown virtual pixels are refused" "--virtual-pixels expects exact-hit or as-placed, got 'smooth'" render --virtual-pixels smooth
fails_with "an unknown search lists the searches" "--search expects crosshair, hierarchy or explosion-map, got 'walk'" render --search walk
fails_with "a G-buffer scale past the bound is refused" "--gbuffer-scale expects a number in [0.125, 4], got '8'" render --gbuffer-scale 8
fails_with "a non-numeric G-buffer scale is refused" "--gbuffer-scale expects a number in [0.125, 4]" render --gbuffer-scale fine
fails_with "a G-buffer precision other than 32 or 16 is refused" "--gbuffer-precision expects 32 or 16" render --gbuffer-precision 8
fails_with "a cube face past the bound is refused" "--environment-size expects an integer in [8, 2048]" render --environment-size 4096
fails_with "a margin past the bound is refused" "--margin expects a number in [0, 1]" render --margin 2
fails_with "a bad plan scope names the choices" "--plan expects needed or everything, got 'some'" render --plan some
output=$("$specula" render --scene checker-sphere --size 96x72 --out "$work/p.png" 2>&1)
check "render prints the plan per mirror part: a small mirror is ray-cast" grep -q "plan: mirror 'mirror-sphere' part 0 (convex, ~[0-9]* px): ray-cast 1 objects (289 vertices); 0 objects" <<<"$output"
check "... and runs no search" lacks "$output" ' search '
output=$("$specula" render --scene checker-sphere --size 96x72 --ray-cast never --out "$work/p0.png" 2>&1)
check "--ray-cast never searches every mirror" grep -q "plan: mirror 'mirror-sphere' part 0 (convex, ~[0-9]* px): searched 1 objects (289 vertices)" <<<"$output"
fails_with "an unknown ray-cast rule is refused by name" "--ray-cast expects cheaper, never or always, got 'sometimes'" render --ray-cast sometimes
# A search or method the user names is what runs; the cost model chooses only by default.
for named in "--search hierarchy" "--search crosshair" "--method explosion-map"; do
  output=$("$specula" render --scene checker-sphere --size 96x72 $named --out "$work/named.png" 2>&1)
  check "$named runs the search, not the ray cast the cost model prefers" \
    grep -q "plan: mirror 'mirror-sphere' part 0 (convex, ~[0-9]* px): searched 1 objects (289 vertices)" <<<"$output"
done
output=$("$specula" render --scene checker-sphere --size 96x72 --search hierarchy --ray-cast cheaper --out "$work/named.png" 2>&1)
check "--ray-cast given beside --search is obeyed" grep -q "part 0 (convex, ~[0-9]* px): ray-cast 1 objects" <<<"$output"
check "a searched mirror says how many uncovered pixels it ray-cast" grep -q "behind it or in its shadow); 0 objects (0 vertices) under the 0.5 px error budget; [0-9]* uncovered pixels ray-cast" <<<"$output"
output=$("$specula" render --scene checker-sphere --size 96x72 --ray-cast never --uncovered background --out "$work/pb.png" 2>&1)
check "--uncovered background ray-casts none" grep -q "; 0 uncovered pixels ray-cast" <<<"$output"
output=$("$specula" render --scene checker-sphere --size 16x12 --error-budget 16 --out "$work/tiny.png" 2>&1)
check "a mirror narrower than the error budget shows its own colour" grep -q "plan: mirror 'mirror-sphere' part 0 (convex, ~[0-9]* px): own colour, drew 0 objects (0 vertices); 0 objects, 0 vertices left out (behind it or in its shadow); 1 objects (289 vertices) under the 16 px error budget" <<<"$output"
fails_with "a negative error budget is refused by name" "--error-budget expects a number in [0, 16], got '-1'" render --error-budget -1
fails_with "an unknown uncovered-pixel fill names the choices" "--uncovered expects ray-cast or background, got 'grey'" render --uncovered grey
check "--plan everything renders too" "$specula" render --scene checker-sphere --size 96x72 --plan everything --out "$work/pe.png"
"$specula" render --method environment-map --environment-size 32 --gbuffer-scale 0.5 --gbuffer-precision 16 --size 96x72 --out "$work/env.png" >"$work/env.txt" 2>&1
check "the environment-map method renders with the G-buffer options" test $? -eq 0
check "... and runs the environment-map pass, not the search" bash -c "grep -q 'environment-map' '$work/env.txt' && ! grep -q ' search ' '$work/env.txt'"
check "... and writes a PNG" bash -c "head -c 8 '$work/env.png' | od -An -tx1 | grep -q '89 50 4e 47'"
fails_with "an unknown command shows the commands" "unknown command 'paint'" paint
"$specula" render --help >"$work/help.txt"
check "render --help lists every option" bash -c "for o in scene size eye target up fov time plan ray-cast error-budget uncovered tessellation metric threshold level explosion-map-size explosion-refine explosion-placement virtual-pixels out gl; do grep -q -- \"--\$o \" '$work/help.txt' || exit 1; done"
check "specula --help lists render and scenes" bash -c "'$specula' --help | grep -q '^  render' && '$specula' --help | grep -q '^  scenes'"

output=$(SPECULA_GL_DEBUG=1 "$specula" render --scene quad --size 64x48 --out "$work/debug.png" 2>&1)
check "SPECULA_GL_DEBUG turns the driver's messages on and says so" grep -q "GL debug output on (SPECULA_GL_DEBUG)" <<<"$output"
gpu_check="$(dirname "$0")/../../docker/gpu-check.sh"
build="$(dirname "$specula")/.."
output=$("$gpu_check" "$work/no-build" "$work/gc" 2>&1); status=$?
check "gpu-check without a build says how to build" bash -c "[[ $status == 2 ]] && grep -q 'build first' <<<\"\$0\"" "$output"
output=$(GL=glx "$gpu_check" "$build" "$work/gc" 2>&1); status=$?
check "gpu-check without a usable GL stops at once and says why" bash -c "[[ $status == 1 ]] && grep -q -- '--gl expects auto' <<<\"\$0\"" "$output"

finish
