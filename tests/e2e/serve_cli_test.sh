#!/usr/bin/env bash
# `specula serve` and `specula bench serve` options and outputs as a user meets them (the protocol
# itself is tested in tests/net).
# usage: serve_cli_test.sh PATH/TO/specula
set -uo pipefail
specula="$1"
source "$(dirname "$0")/checks.sh"

check "serve --help names every route" bash -c "'$specula' serve --help | grep -q '/healthz' && '$specula' serve --help | grep -q '/metrics' && '$specula' serve --help | grep -q 'specula.v1.json'"
check "serve --help lists every option" bash -c "for o in bind port scene max-sessions token web-root render-threads encode-threads max-fps still-delay max-size tessellation gl; do '$specula' serve --help | grep -q -- \"--\$o\" || exit 1; done"
check "specula --help lists serve" bash -c "'$specula' --help | grep -q '^  serve'"
fails_with "a bad port names the option" "--port expects an integer in [0, 65535]" serve --port 70000
fails_with "a bad session limit names the option" "--max-sessions expects an integer" serve --max-sessions 0
fails_with "an accuracy sample count out of range names the option" "--accuracy-samples" serve --accuracy-samples 70000
fails_with "an accuracy target out of range names the option" "--accuracy-target" serve --accuracy-target 101
fails_with "an accuracy target without the estimate is refused" "--accuracy-target needs the live estimate" serve --accuracy-target 1 --accuracy-samples 0
fails_with "an unknown scene fails before listening" "neither a built-in scene" serve --scene nope --port 0
fails_with "a non-loopback bind needs a token" "without a token" serve --bind 0.0.0.0 --port 0
fails_with "a bad bind address is named" "is not an IP address" serve --bind not-an-ip --token t --port 0

# bench serve: one row per (sessions, size), real frames from the GL renderer.
output=$("$specula" bench serve --scene quad --sessions 1,2 --sizes 96x64 --seconds 1 --warmup 0.5 \
  --csv "$work/s.csv" --json "$work/s.json" 2>"$work/progress.txt")
check "bench serve succeeds" test $? -eq 0
check "bench serve shows progress" grep -q "bench serve \[2/2\] 2 x 96x64" "$work/progress.txt"
check "its CSV has a header and two rows" test "$(wc -l <"$work/s.csv")" -eq 3
columns=$(head -1 "$work/s.csv" | tr ',' '\n' | wc -l)
check "every CSV row has the header's columns" awk -F, -v n="$columns" 'NF != n { exit 1 }' "$work/s.csv"
value() { awk -F, -v sessions="$1" -v column="$2" 'NR == 1 { for (i = 1; i <= NF; i++) at[$i] = i } $2 == sessions { print $at[column] }' "$work/s.csv"; }
check "one session gets frames" awk -v f="$(value 1 fps_per_session_mean)" 'BEGIN { exit !(f > 0) }'
check "latency is measured" awk -v a="$(value 1 latency_ms_p50)" -v b="$(value 1 latency_ms_p99)" 'BEGIN { exit !(a > 0 && b >= a) }'
check "frames have bytes" awk -v b="$(value 2 bytes_per_frame)" 'BEGIN { exit !(b > 100) }'
check "no session failed" test "$(value 2 errors)" = 0
check "the table has a row per configuration" contains "$output" '^ \+1 \+96x64' '^ \+2 \+96x64'
check "the JSON has both runs" test "$(grep -c '"fps_per_session_mean"' "$work/s.json")" -eq 2
# bench serve --instances: two `specula serve` processes behind HAProxy; one is killed in the last run.
haproxy_config="$(dirname "$0")/../../docker/haproxy/specula.cfg"
output=$("$specula" bench serve --scene quad --instances 2 --haproxy-config "$haproxy_config" --sessions 2 --sizes 64x48 --seconds 3 \
  --warmup 0.5 --csv "$work/i.csv" --json "$work/i.json" 2>"$work/iprogress.txt")
check "bench serve --instances succeeds" test $? -eq 0
check "the sessions spread one a piece" contains "$output" '^ \+2 \+64x48 .* 1/1$'
check "killing an instance moves its session, resumed" contains "$output" \
  'instance 0 killed a third of the way into 2 sessions at 64x48 (sessions per instance 1/1, then -/2): 1 reconnected, 1 resumed'
check "... without errors" contains "$output" ' 0 errors$'
fails_with "bench serve --instances names a missing HAProxy configuration" "HAProxy's configuration /nonexistent.cfg is missing" bench serve --instances 2 --haproxy-config /nonexistent.cfg
fails_with "bench serve checks its lists" "--sizes expects WIDTHxHEIGHT" bench serve --sizes 640x
fails_with "bench serve checks session counts" "--sessions expects an integer in [1, 256]" bench serve --sessions 1,0
fails_with "bench serve checks its outputs before work" "could not write '$work/no/dir/s.csv'" bench serve --csv "$work/no/dir/s.csv"
finish
