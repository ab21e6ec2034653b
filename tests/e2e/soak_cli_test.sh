#!/usr/bin/env bash
# `specula bench soak` in its short form: one minute of 8 real sessions (every client role, reconnect
# storms included) against a real `specula serve` on software GL. It must pass, and its table, summary,
# CSV and JSON must have what the 10-minute run reports. 8 sessions, not 16: on a 2-core llvmpipe machine
# 16 get about one frame a second each, and the short form is about the checks, not the load.
# usage: soak_cli_test.sh PATH/TO/specula
set -uo pipefail
specula="$1"
source "$(dirname "$0")/checks.sh"

fails_with "a run of no time is refused before the server starts" "--minutes expects" bench soak --minutes 0
fails_with "a warm-up as long as the run is refused" "--warmup expects" bench soak --minutes 1 --warmup 60

"$specula" bench soak --minutes 1 --sessions 8 --csv "$work/soak.csv" --json "$work/soak.json" \
  >"$work/out.txt" 2>"$work/progress.txt"
check "a one-minute soak with 8 sessions passes" test $? -eq 0
output=$(cat "$work/out.txt")
check "the table has its columns" contains "$output" \
  '^ *s *RSS MiB *fds *GL objects *sessions *frames sent *received *skipped *timeouts *resumed$'
check "the table has a row a sample, from 0 s to 60 s" contains "$output" '^ *0  ' '^ *60  '
check "the summary names frames, latency and the three trends" contains "$output" '^frames delivered [1-9]' \
  '^input-to-frame latency ms: .* p99 [0-9]' '^RSS MiB .* at start' '^fds .* at start' '^GL objects .* at start'
check "the clients stormed, dropped, stopped and changed settings" contains "$output" \
  ' [1-9][0-9]* storms, [1-9][0-9]* abrupt drops, [1-9][0-9]* stops, [1-9][0-9]* settings changes'
check "the counters agree with the clients" contains "$output" '^ok - frames sent' '^ok - resumes counted' \
  '^ok - no session left open'
check "the stopped readers' thin pipes filled: the server skipped frames and dropped them at its deadline" contains \
  "$output" ', [1-9][0-9]* skipped by the server; [1-9][0-9]* connections dropped at the write deadline$' \
  '^ok - connections dropped at the write deadline [1-9][0-9]*: at least the [1-9][0-9]* stops (of [1-9][0-9]*) the server ended'
check "it says PASS" contains "$output" '^PASS$'
check "progress goes to stderr as samples arrive" grep -q '^bench soak: 8 sessions for 60 s' "$work/progress.txt"
check "the CSV has its header" grep -qx 'seconds,rss_mib,fds,gl_objects,sessions,frames_sent,frames_received,frames_skipped,write_timeouts,sessions_opened,sessions_resumed,resumes_refused' "$work/soak.csv"
check "the CSV has a row a sample" test "$(wc -l <"$work/soak.csv")" -ge 12
check "the JSON says it passed and has the trends" python3 -c '
import json, sys
report = json.load(open(sys.argv[1]))
assert report["passed"] is True
assert set(report["trends"]) == {"rss_mib", "fds", "gl_objects"}
assert report["samples"][-1]["gl_objects"] > 0
' "$work/soak.json"
finish
