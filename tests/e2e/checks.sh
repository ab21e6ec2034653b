# Shared by the end-to-end scripts: `source` it after setting $specula. Counts passes and failures;
# call `finish` last for the summary and exit status.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0
check() {  # check DESCRIPTION COMMAND...: the command must succeed
  local description="$1"; shift
  if "$@"; then echo "ok - $description"; passes=$((passes + 1)); else echo "FAIL - $description"; failures=$((failures + 1)); fi
}
fails_with() {  # fails_with DESCRIPTION EXPECTED-TEXT ARGS...: specula must exit non-zero and print the text
  local description="$1" expected="$2"; shift 2
  local output
  if output=$("$specula" "$@" 2>&1); then
    echo "FAIL - $description: exited 0"; failures=$((failures + 1))
  elif [[ "$output" != *"$expected"* ]]; then
    echo "FAIL - $description: output lacks '$expected':"; echo "$output"; failures=$((failures + 1))
  else
    echo "ok - $description"; passes=$((passes + 1))
  fi
}
contains() {  # contains TEXT PATTERN...: each grep pattern matches a line of TEXT (captured output)
  local text="$1" pattern; shift
  for pattern in "$@"; do
    grep -q -e "$pattern" <<<"$text" || { printf 'no line matches %s in:\n%s\n' "$pattern" "$text"; return 1; }
  done
}
lacks() {  # lacks TEXT PATTERN: no line of TEXT matches; grep itself failing (status 2) fails too
  local status
  grep -q -e "$2" <<<"$1"
  status=$?
  [[ $status == 1 ]]
}
finish() {
  echo "$passes passed, $failures failed"
  [[ $failures -eq 0 ]]
}
