#!/usr/bin/env bash
# Every C++ file follows .clang-format: names each file that does not, and how to fix it.
# usage: check_format.sh REPOSITORY_ROOT
set -uo pipefail
cd "$1" || exit 2
command -v clang-format >/dev/null || { echo "clang-format is missing: run docker/install-deps.sh" >&2; exit 2; }
mapfile -t files < <(find server client proto tests -name '*.cpp' -o -name '*.h' | sort)
unformatted=()
for file in "${files[@]}"; do
  clang-format --style=file --dry-run --Werror "$file" >/dev/null 2>&1 || unformatted+=("$file")
done
if (( ${#unformatted[@]} > 0 )); then
  printf 'not formatted: %s\n' "${unformatted[@]}"
  echo "fix with: clang-format -i --style=file ${unformatted[*]}"
  exit 1
fi
echo "${#files[@]} C++ files follow .clang-format"
