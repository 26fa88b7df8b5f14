#!/usr/bin/env bash
# Installs what foresight needs to build, test and draw on a fresh Debian (bookworm) machine.
# Idempotent: packages already present are skipped, so a second run costs a second.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libbullet-dev libbullet-extras-dev liburdfdom-dev libassimp-dev
  librsvg2-bin
  clang libclang-rt-14-dev
  python3 pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib
  python3-venv python3-pip python3-setuptools python3-wheel
  parallel slurm-wlm munge
  chromium
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# npm (Debian's, unless a Node.js with its own npm is installed already: the two conflict).
command -v npm >/dev/null || missing+=(npm)
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  echo "setup: installing ${missing[*]}" >&2
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# three.js for the 3D viewer pages (docs/VIEWER.md), from the npm registry at the version
# report/viewer/package-lock.json pins; the build inlines its files into every page.
viewer="$(cd "$(dirname "$0")/.." && pwd)/report/viewer"
wanted="$(sed -n 's/.*"three": "\([0-9.]*\)".*/\1/p' "$viewer/package.json")"
installed="$(sed -n 's/^  "version": "\([0-9.]*\)".*/\1/p' "$viewer/node_modules/three/package.json" 2>/dev/null || true)"
if [ "$installed" != "$wanted" ]; then
  echo "setup: npm ci in report/viewer (three.js $wanted)" >&2
  (cd "$viewer" && npm ci --no-audit --no-fund --silent)
fi
