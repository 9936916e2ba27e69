#!/usr/bin/env bash
# Installs the Debian 12 packages levrt builds and tests with. Skips apt entirely when they are
# all present, so it is cheap to call before every build. Needs root (or sudo) for apt-get.
set -euo pipefail
packages=(
  cmake g++ make ninja-build pkg-config
  libglm-dev libembree-dev libtbb-dev libstb-dev
  libcli11-dev nlohmann-json3-dev libtinygltf-dev libgtest-dev libbenchmark-dev
  libglfw3-dev libimgui-dev libgl-dev libopengl-dev libegl-dev libx11-dev
  xvfb xauth mesa-utils xdotool
  clang python3
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "install-deps: installing ${missing[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
