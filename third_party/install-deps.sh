#!/usr/bin/env bash
# Installs the Debian 12 packages levrt builds and tests with, then the Khronos glTF-Validator
# from the npm registry (tests/app/gltf_validator_test.cpp; a pinned version, global). Skips apt
# and npm when everything is present, so it is cheap to call before every build. Needs root (or
# sudo) for apt-get and the global npm install.
set -euo pipefail
packages=(
  cmake g++ make ninja-build pkg-config
  libglm-dev libembree-dev libtbb-dev libstb-dev
  libcli11-dev nlohmann-json3-dev libtinygltf-dev libtinyexr-dev libgtest-dev libbenchmark-dev
  libglfw3-dev libimgui-dev libgl-dev libopengl-dev libegl-dev libx11-dev
  xvfb xauth mesa-utils xdotool
  clang clang-format python3
)
gltf_validator="gltf-validator@2.0.0-dev.3.10"
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# node and npm from Debian, unless a node is already installed another way (its own npm).
command -v node >/dev/null && command -v npm >/dev/null || missing+=(nodejs npm)
sudo=""""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
if [ ${#missing[@]} -ne 0 ]; then
  echo "install-deps: installing ${missing[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
if ! npm ls -g "$gltf_validator" >/dev/null 2>&1; then
  echo "install-deps: installing $gltf_validator (npm)" >&2
  $sudo npm install -g --no-fund --no-audit "$gltf_validator" >/dev/null
fi
