#!/usr/bin/env bash
# Lints the deployment beside the images: the Kubernetes manifests (yamllint -s, rules in
# .yamllint) and the HAProxy front (haproxy -c, warnings fatal) with each backend file, plus a
# loopback backend of the kind a test harness writes, and builds both kustomize variants with kubectl
# (Debian 12's 1.20 and today's alike), checking that every Secret and ConfigMap they reference is
# one they generate. Needs haproxy, yamllint and kubectl (docker/install-deps.sh installs them);
# ctest runs it as e2e.deploy_lint.
# Usage: docker/lint-deploy.sh   (from anywhere)
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

missing=()
command -v haproxy >/dev/null || missing+=("haproxy (Debian package haproxy)")
command -v yamllint >/dev/null || missing+=("yamllint (Debian package yamllint)")
command -v kubectl >/dev/null || missing+=("kubectl (Debian package kubernetes-client)")
if (( ${#missing[@]} )); then
  for m in "${missing[@]}"; do echo "lint-deploy: $m is not installed" >&2; done
  echo "lint-deploy: install with docker/install-deps.sh, or apt-get install haproxy yamllint kubernetes-client" >&2
  exit 1
fi

failures=0
passes=0
pass() { echo "ok - $1"; passes=$((passes + 1)); }
fail() { echo "FAIL - $1"; [[ -n ${2:-} ]] && printf '%s\n' "$2" | sed 's/^/    /'; failures=$((failures + 1)); }

# yamllint -s: warnings fail too. The adapter values and kustomizations are YAML like the rest.
yaml=(docker/k8s docker/haproxy/kustomization.yaml .yamllint)
if output=$(cd "$root" && yamllint -s -c .yamllint "${yaml[@]}" 2>&1); then
  pass "yamllint -s ${yaml[*]} ($(cd "$root" && find docker/k8s -name '*.yaml' | wc -l) files in docker/k8s)"
else
  fail "yamllint -s ${yaml[*]}" "$output"
fi

# haproxy_check DESCRIPTION BACKEND-FILE: the shared file and one backend must load without a warning.
# The one warning allowed is a resolvers section on a machine whose /etc/resolv.conf names no server:
# the cluster's or Docker's DNS is there in production.
haproxy_check() {
  local description="$1" backend="$2" output warnings
  if ! output=$(SPECULA_FRONT_BIND=127.0.0.1:18080 SPECULA_HAPROXY_SOCKET="$work/haproxy.sock" \
      SPECULA_INSTANCES_DNS=specula-instances.default.svc.cluster.local \
      haproxy -c -f "$root/docker/haproxy/specula.cfg" -f "$backend" 2>&1); then
    fail "$description" "$output"
    return
  fi
  warnings=$(grep -E '\[(WARNING|ALERT)\]' <<<"$output" | grep -v 'has no nameservers configured')
  if [[ -n $warnings ]]; then fail "$description: warnings" "$warnings"; else pass "$description"; fi
}
haproxy_check "haproxy -c specula.cfg + backend-compose.cfg" "$root/docker/haproxy/backend-compose.cfg"
haproxy_check "haproxy -c specula.cfg + backend-kubernetes.cfg" "$root/docker/haproxy/backend-kubernetes.cfg"
cat >"$work/backend-loopback.cfg" <<'EOF'
backend specula from specula
    server s1 127.0.0.1:18081
    server s2 127.0.0.1:18082
EOF
haproxy_check "haproxy -c specula.cfg + a loopback backend (server sN 127.0.0.1:PORT)" "$work/backend-loopback.cfg"
if output=$(SPECULA_FRONT_BIND= haproxy -c -f "$root/docker/haproxy/specula.cfg" -f "$work/backend-loopback.cfg" 2>&1); then
  fail "an empty SPECULA_FRONT_BIND is refused: haproxy -c passed"
elif ! grep -q 'SPECULA_FRONT_BIND is set but empty' <<<"$output"; then
  fail "an empty SPECULA_FRONT_BIND is refused with its name" "$output"
else
  pass "an empty SPECULA_FRONT_BIND is refused with its name"
fi

# Names the manifests reference (secretKeyRef, configMap volumes) that no object in them has.
dangling_references() {
  python3 -c '
import sys, yaml
docs = [d for d in yaml.safe_load_all(sys.stdin) if d]
have = {(d["kind"], d["metadata"]["name"]) for d in docs}
def walk(node):
    if isinstance(node, dict):
        for key, kind in (("secretKeyRef", "Secret"), ("configMap", "ConfigMap"), ("secret", "Secret")):
            if isinstance(node.get(key), dict):
                name = node[key].get("name") or node[key].get("secretName")
                if name and (kind, name) not in have: print(kind, name)
        for value in node.values(): walk(value)
    elif isinstance(node, list):
        for value in node: walk(value)
walk(docs)'
}

# kustomize: both variants build (with a throwaway secrets file in a copy of docker/).
cp -r "$root/docker" "$work/docker"
printf 'SPECULA_TOKEN=lint\nSPECULA_RESUME_SECRET=%s\n' "$(printf 'x%.0s' {1..32})" >"$work/docker/k8s/secrets/specula.env"
kubectl_version=$(kubectl version --client 2>/dev/null | grep -oE 'v[0-9]+\.[0-9]+\.[0-9]+' | head -1)
for variant in docker/k8s docker/k8s/nvidia; do
  # stderr apart: today's kubectl warns that the spellings Debian 12's needs are deprecated.
  if output=$(kubectl kustomize "$work/$variant" 2>"$work/kustomize.err"); then
    kinds=$(grep -E '^kind: ' <<<"$output" | sed 's/kind: //' | sort | uniq -c | awk '{ printf "%s%s %s", sep, $1, $2; sep = ", " }')
    pass "kubectl ${kubectl_version:-?} kustomize $variant: $kinds"
    dangling=$(dangling_references <<<"$output")
    if [[ -n $dangling ]]; then fail "$variant references what it does not generate" "$dangling"; else pass "$variant: every Secret and ConfigMap referenced is generated"; fi
  else
    fail "kubectl kustomize $variant" "$(cat "$work/kustomize.err")"
  fi
done

echo "$passes passed, $failures failed"
[[ $failures -eq 0 ]]
