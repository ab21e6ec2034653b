#!/usr/bin/env bash
# The thin clients against a real `specula serve`: specula-path (JSON and CSV paths, both paces),
# specula-load (small N, short run, JSON output), specula-view under Xvfb, and their errors.
# usage: clients_cli_test.sh PATH/TO/bin (holding specula, specula-path, specula-load, specula-view)
set -uo pipefail
bin="$1"
specula="$bin/specula"
source "$(dirname "$0")/checks.sh"

"$specula" serve --port 0 --scene quad >"$work/serve.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null; wait $server 2>/dev/null; rm -rf "$work"' EXIT
for _ in $(seq 600); do grep -q "listening on" "$work/serve.log" && break; sleep 0.1; done
port=$(sed -n 's/.*listening on 127\.0\.0\.1:\([0-9]*\).*/\1/p' "$work/serve.log")
check "the server is listening" test -n "$port"
url="ws://127.0.0.1:$port"

cat >"$work/path.json" <<'JSON'
{"keys": [{"time": 0, "eye": [0, 1, 5], "target": [0, 0, 0], "fov": 45, "scene_time": 0},
          {"time": 1, "eye": [3, 1, 4], "target": [0, 0, 0], "fov": 40, "scene_time": 2}]}
JSON
"$bin/specula-path" --url "$url" --path "$work/path.json" --fps 4 --size 120x80 --csv "$work/path.csv" \
  --frames-dir "$work/frames" >"$work/path.out" 2>"$work/path.err"
check "specula-path plays a JSON path" test $? -eq 0
check "it prints a summary" grep -q "^5 samples, [0-9]* frames in .* latency p50 .* ms" "$work/path.out"
check "its CSV has a row per frame with every column" awk -F, 'NR == 1 { n = NF } NR > 1 && NF != n { exit 1 } END { exit !(NR >= 6) }' "$work/path.csv"
check "every sample got a frame reflecting it (pace frames)" bash -c "for s in 1 2 3 4 5; do awk -F, -v s=\$s 'NR > 1 && \$3 == s { found = 1 } END { exit !found }' '$work/path.csv' || exit 1; done"
check "the frames reflect the path's scene time" awk -F, 'NR > 1 && $3 == 5 && $13 == 2000 { found = 1 } END { exit !found }' "$work/path.csv"
check "it wrote every frame as JPEG" test "$(ls "$work/frames" | wc -l)" -eq "$(($(wc -l <"$work/path.csv") - 1))"
check "the JPEGs are JPEGs" bash -c "head -c 2 '$work/frames/frame_00001.jpg' | od -An -tx1 | grep -q 'ff d8'"
check "it shows progress" grep -q "sample 5/5" "$work/path.err"
check "its CSV carries the live accuracy estimate of earlier frames" awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i } NR > 1 && $c["accuracy_sampled"] > 0 && $c["accuracy_frame"] < $c["frame"] && $c["accuracy_low"] <= $c["accuracy_mismatch"] && $c["accuracy_mismatch"] <= $c["accuracy_high"] { found = 1 } END { exit !found }' "$work/path.csv"
check "its summary states the estimate" grep -q "^mirror mismatch, live estimate: last [0-9]* frames .* %" "$work/path.out"

printf 'time,eye_x,eye_y,eye_z,target_x,target_y,target_z,fov\n0,0,1,5,0,0,0,45\n0.5,2,1,4,0,0,0,45\n' >"$work/path.csv.in"
mv "$work/path.csv.in" "$work/keys.csv"
"$bin/specula-path" --url "$url" --path "$work/keys.csv" --pace realtime --fps 10 --size 64x48 --csv "$work/rt.csv" >"$work/rt.out" 2>&1
check "specula-path plays a CSV path in real time" test $? -eq 0
check "the real-time run records frames" test "$(wc -l <"$work/rt.csv")" -gt 1

printf 'time,eye_x\n0,1\n' >"$work/bad.csv"
"$bin/specula-path" --url "$url" --path "$work/bad.csv" >"$work/bad.out" 2>&1
check "a path without its columns is refused by name" bash -c "grep -q \"lacks column 'eye_y'\" '$work/bad.out'"
"$bin/specula-path" --url "ws://127.0.0.1:1" --path "$work/path.json" --csv "$work/x.csv" >"$work/down.out" 2>&1
check "specula-path says when the server is unreachable" bash -c "grep -q 'cannot connect to 127.0.0.1:1' '$work/down.out'"

"$bin/specula-load" --url "$url" --sessions 3 --seconds 1 --warmup 0.5 --size 96x64 --json "$work/load.json" >"$work/load.out" 2>"$work/load.err"
check "specula-load runs 3 sessions" test $? -eq 0
check "it prints a row per session and the aggregate" bash -c "test \$(grep -cE '^ +[123] ' '$work/load.out') -eq 3 && grep -q '^all .*fps/session' '$work/load.out'"
check "its JSON has the aggregate and 3 sessions" bash -c "grep -q '\"fps_per_session_mean\"' '$work/load.json' && test \$(grep -c '\"fps\":' '$work/load.json') -eq 3"
check "no session failed" grep -q '"errors": 0' "$work/load.json"
check "it shows live progress" grep -q "specula-load: 1/1 s" "$work/load.err"
check "its summary states the live accuracy estimate" grep -qE "^accuracy  [1-9][0-9]* frames estimated live: mirror mismatch mean [0-9.]+ %" "$work/load.out"
check "its JSON has the estimate" grep -q '"mirror_mismatch_worst_high"' "$work/load.json"
"$bin/specula-load" --url "ws://127.0.0.1:1" --seconds 1 >"$work/ldown.out" 2>&1
check "specula-load says when the server is unreachable" bash -c "grep -q 'cannot connect to 127.0.0.1:1' '$work/ldown.out'"

xvfb-run -a "$bin/specula-view" --url "$url" --frames 3 --seconds 60 --size 320x180 --screenshot "$work/view.png" >"$work/view.out" 2>&1
check "specula-view runs under Xvfb, draws frames and exits cleanly" test $? -eq 0
check "it reports the frames it drew" grep -q "specula-view: drew 3 frames" "$work/view.out"
# A blank 320x180 window compresses to a few hundred bytes; the quad scene's window to several KB.
check "its window showed the scene, not a blank" test "$(stat -c %s "$work/view.png")" -gt 3000
"$bin/specula-view" --url "ws://127.0.0.1:1" >"$work/vdown.out" 2>&1
check "specula-view says when the server is unreachable" bash -c "grep -q 'cannot connect to 127.0.0.1:1' '$work/vdown.out'"

# A server that dies mid-path comes back on the same port with the same resume secret: specula-path
# reconnects, resumes its session and says so, and the run ends well.
head -c 48 /dev/urandom | base64 >"$work/resume.secret"
"$specula" serve --port 0 --scene quad --resume-secret-file "$work/resume.secret" >"$work/first.log" 2>&1 &
first=$!
for _ in $(seq 600); do grep -q "listening on" "$work/first.log" && break; sleep 0.1; done
port2=$(sed -n 's/.*listening on 127\.0\.0\.1:\([0-9]*\).*/\1/p' "$work/first.log")
cat >"$work/long.json" <<'JSON'
{"keys": [{"time": 0, "eye": [0, 1, 5], "target": [0, 0, 0], "fov": 45}, {"time": 4, "eye": [3, 1, 4], "target": [0, 0, 0], "fov": 40}]}
JSON
"$bin/specula-path" --url "ws://127.0.0.1:$port2" --path "$work/long.json" --pace realtime --fps 10 --size 64x48 \
  --csv "$work/resumed.csv" >"$work/resumed.out" 2>"$work/resumed.err" &
path=$!
sleep 1.5
kill -9 $first; wait $first 2>/dev/null
"$specula" serve --port "$port2" --scene quad --resume-secret-file "$work/resume.secret" >"$work/second.log" 2>&1 &
second=$!
wait $path
check "specula-path outlives its server's restart" test $? -eq 0
check "it says it lost the connection and is reconnecting" grep -q "connection lost .*: reconnecting (attempt 1 of 8)" "$work/resumed.err"
check "it says the session was resumed (Welcome.resumed from the restarted server)" grep -q "resumed the session on a new connection" "$work/resumed.err"
kill $second 2>/dev/null; wait $second 2>/dev/null

# Garbage options are refused by name before anything connects.
tool_fails_with() {  # tool_fails_with DESCRIPTION EXPECTED-TEXT TOOL ARGS...
  local description="$1" expected="$2" tool="$3"; shift 3
  local output
  if output=$("$bin/$tool" "$@" 2>&1); then check "$description (exited 0)" false
  else check "$description" grep -qF -- "$expected" <<<"$output"; fi
}
tool_fails_with "specula-load refuses zero sessions" "--sessions expects an integer in [1, 1024]" specula-load --sessions 0
tool_fails_with "specula-load refuses a bad size" "--size expects WIDTHxHEIGHT" specula-load --size big
tool_fails_with "specula-load refuses a bad encoding" "--encoding expects proto or json, got 'xml'" specula-load --encoding xml
tool_fails_with "specula-load refuses a bad URL" "the port must be a number" specula-load --url ws://127.0.0.1:99999
tool_fails_with "specula-path needs a path" "--path FILE is required" specula-path
tool_fails_with "specula-path refuses a bad pace" "--pace expects frames or realtime" specula-path --path "$work/path.json" --pace fast
tool_fails_with "specula-view refuses a bad frame count" "--frames expects an integer" specula-view --frames -1
tool_fails_with "unknown options are named" "unknown option --colour" specula-view --colour red

for tool in specula-path specula-load specula-view; do
  check "$tool --help tells what it does" bash -c "'$bin/$tool' --help | grep -q -- '--url'"
done
finish
