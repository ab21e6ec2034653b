#!/usr/bin/env bash
# The one list of Specula's build and run dependencies (Debian 12 packages).
# Used by the README, .ci/run and both Dockerfiles, so they never disagree.
#   docker/install-deps.sh           build + runtime + test dependencies
#   docker/install-deps.sh --build   build + runtime: enough to build and run specula (no browser, no X)
#   docker/install-deps.sh --runtime only what the built binaries need at run time
set -euo pipefail

runtime_packages=(
  libegl1 libegl-mesa0 libgl1-mesa-dri libosmesa6   # headless GL: EGL (device/surfaceless) and OSMesa
  libglfw3 libturbojpeg0 libprotobuf32 libembree3-3  # clients, JPEG, protocol, reference ray tracer
  libssl3                                            # HMAC-SHA256 of signed resume tokens
  gnuplot-nox                                        # specula bench accuracy draws its error/time plot
  ca-certificates
)
build_packages=(
  build-essential cmake ninja-build pkg-config git
  libglm-dev libegl-dev libgl-dev libosmesa6-dev libglfw3-dev
  libturbojpeg0-dev libboost-dev libprotobuf-dev protobuf-compiler
  libembree-dev libtinygltf-dev libtinyobjloader-dev nlohmann-json3-dev libstb-dev libssl-dev
  libcli11-dev          # command lines: parsing, subcommands and --help
  libgtest-dev          # the test suite is configured with the build (small)
)
test_packages=(
  chromium xvfb xauth   # tests: the browser client in headless Chromium, specula-view under Xvfb
  haproxy yamllint      # docker/lint-deploy.sh: the HAProxy front and the Kubernetes manifests
  python3               # tests: the documentation check (links and quoted commands)
  clang-format          # tests: the code follows .clang-format
  clang libclang-rt-14-dev  # tests: the libFuzzer targets (label fuzz), with ASan and UBSan
)

mode="${1:-}"
case "$mode" in
  ""|--build|--runtime) ;;
  *) echo "install-deps: unknown option '$mode'; use no option (everything), --build or --runtime" >&2; exit 2 ;;
esac
packages=("${runtime_packages[@]}")
if [[ "$mode" != "--runtime" ]]; then
  packages+=("${build_packages[@]}")
fi
if [[ -z "$mode" ]]; then
  packages+=("${test_packages[@]}")
  # The browser test drives Chromium over a pipe from any Node >= 18 (Debian 12 has 18); keep one that is there.
  command -v node >/dev/null || packages+=(nodejs)
  # docker/lint-deploy.sh builds the Kustomize variants; keep a kubectl that is there (another package owns it).
  command -v kubectl >/dev/null || packages+=(kubernetes-client)
fi

sudo=""
if [[ "$(id -u)" != 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root or install sudo" >&2; exit 1; }
  sudo="sudo"
fi

# Skip apt entirely when everything is present: keeps re-runs fast and offline-friendly.
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if (( ${#missing[@]} == 0 )); then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi
echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
