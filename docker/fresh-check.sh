#!/usr/bin/env bash
# Runs the README's two commands where nothing else was ever installed: a minimal Debian 12 root file
# system (mmdebstrap, variant apt), a clean clone of this repository's HEAD in it, and README command 1
# then command 2 run inside it by chroot as root with CI=true, read from README.md, not copied here.
# Writes OUT_DIR/summary.md (versions, each command's exit status and time, the test summary) and the
# tail of each command's log. Needs root, mmdebstrap (apt-get install mmdebstrap) and the Debian mirror;
# takes about 45 minutes and 8 GiB under /var/tmp on 2 cores.
# usage: docker/fresh-check.sh [OUT_DIR]   (default: bench-results/fresh-check)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-$repo/bench-results/fresh-check}")
(( EUID == 0 )) || { echo "fresh-check: needs root (mmdebstrap and chroot)" >&2; exit 2; }
command -v mmdebstrap >/dev/null || { echo "fresh-check: mmdebstrap is missing: apt-get install mmdebstrap" >&2; exit 2; }

# The two commands are the lines after "# 1." and "# 2." in the README's fenced block.
readme_command() { awk -v mark="# $1." 'index($0, mark) == 1 { getline; print; exit }' "$repo/README.md"; }
commands=("$(readme_command 1)" "$(readme_command 2)")
for i in 0 1; do
  [[ -n ${commands[i]} ]] || { echo "fresh-check: README.md has no line after '# $((i + 1)).'" >&2; exit 1; }
done

work=$(mktemp -d /var/tmp/specula-fresh.XXXXXX)
root="$work/root"
mounted=()
cleanup() {
  local m
  for ((m = ${#mounted[@]} - 1; m >= 0; m--)); do umount -l "${mounted[m]}" 2>/dev/null || true; done
  rm -rf --one-file-system "$work"
}
trap cleanup EXIT

echo "fresh-check: a Debian 12 root in $root"
mmdebstrap --variant=apt --include=ca-certificates bookworm "$root" \
  "deb http://deb.debian.org/debian bookworm main" \
  "deb http://deb.debian.org/debian bookworm-updates main" \
  "deb http://deb.debian.org/debian-security bookworm-security main"
cp /etc/resolv.conf "$root/etc/resolv.conf"
# Committed work only, as CI sees it.
git clone --quiet --no-hardlinks "$repo" "$root/root/specula"
commit=$(git -C "$root/root/specula" rev-parse --short HEAD)
for fs in proc sys dev dev/pts; do
  mount --bind "/$fs" "$root/$fs"
  mounted+=("$root/$fs")
done
mount -t tmpfs -o size=2g tmpfs "$root/dev/shm"  # Chromium's shared memory
mounted+=("$root/dev/shm")

in_root() {
  chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    LANG=C.UTF-8 CI=true DEBIAN_FRONTEND=noninteractive bash -c "cd /root/specula && $1"
}

mkdir -p "$out"
statuses=()
for i in 0 1; do
  log="$work/command-$((i + 1)).log"
  echo "fresh-check: command $((i + 1)): ${commands[i]}"
  start=$(date +%s)
  set +e
  in_root "${commands[i]}" >"$log" 2>&1
  status=$?
  set -e
  statuses+=("$status $(($(date +%s) - start))")
  tail -n 150 "$log" >"$out/command-$((i + 1)).log.tail"
  echo "fresh-check: command $((i + 1)) exited $status after $(($(date +%s) - start)) s"
done

version() { in_root "$1" 2>/dev/null | head -1 || true; }
{
  echo "# The README's two commands in a fresh Debian 12 root"
  echo
  echo "\`docker/fresh-check.sh\` on $(date -u +%Y-%m-%d), commit $commit, host $(nproc) cores."
  echo
  echo "- Debian $(version 'cat /etc/debian_version'); $(version 'g++ --version'); node $(version 'node --version');"
  echo "  kubectl $(version "kubectl version --client 2>/dev/null | grep -oE 'v[0-9.]+' | head -1"); $(version 'chromium --version')"
  echo
  echo "| command | exit status | seconds |"
  echo "|---|---|---|"
  for i in 0 1; do
    read -r status seconds <<<"${statuses[i]}"
    echo "| \`${commands[i]}\` | $status | $seconds |"
  done
  echo
  echo "Test summary (command 2):"
  echo
  echo '```'
  grep -E 'tests passed|tests failed|^\s+[0-9]+ - |Total Test time|sec\*proc' "$work/command-2.log" || echo "(no ctest summary)"
  echo '```'
} >"$out/summary.md"
cat "$out/summary.md"
for entry in "${statuses[@]}"; do [[ ${entry%% *} == 0 ]] || exit 1; done
