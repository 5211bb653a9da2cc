#!/usr/bin/env bash
# Installs everything mrpt_krp_plugin needs on Debian 12 (bookworm).
# Idempotent: when everything is present it only checks and returns in seconds.
# Works as root or through sudo. Never changes the system's apt sources.
#
#   scripts/install_deps.sh            # C++ build + test dependencies, onnxruntime
#
# Environment:
#   KRP_THIRD_PARTY   where onnxruntime is unpacked (default: <repo>/third_party)
#   KRP_ORT_VERSION   onnxruntime library version from PyPI (default below)
set -euo pipefail

REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
THIRD_PARTY="${KRP_THIRD_PARTY:-$REPO_ROOT/third_party}"
# 1.22 library with trixie's 1.21 headers: measured compatible (ORT_API_VERSION 21).
ORT_VERSION="${KRP_ORT_VERSION:-1.22.1}"
ORT_DIR="$THIRD_PARTY/onnxruntime"

if [ "$(id -u)" -eq 0 ]; then SUDO=""; else SUDO="sudo"; fi

APT_PACKAGES=(
  # toolchain
  build-essential cmake git pkg-config python3-venv python3-pip unzip ca-certificates
  # the sanitizer and libFuzzer build (scripts/run_sanitizers.sh)
  clang libclang-rt-14-dev
  # core libraries
  libmrpt-dev mrpt-apps mrpt-common libopencv-dev liboctomap-dev libeigen3-dev
  libgtest-dev libgmock-dev libyaml-cpp-dev nlohmann-json3-dev zlib1g-dev libssl-dev
  # ROS 1 as packaged by Debian (catkin must be named: see shared/notes/dependencies.md)
  catkin libroscpp-dev libsensor-msgs-dev libnav-msgs-dev libgeometry-msgs-dev
  libstd-srvs-dev libtf2-ros-dev librosbag-dev libvisualization-msgs-dev ros-core
  python3-rostopic python3-rosservice python3-std-srvs python3-geometry-msgs
  python3-sensor-msgs python3-nav-msgs
)

missing=()
for p in "${APT_PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ "${#missing[@]}" -gt 0 ]; then
  echo "[install_deps] installing ${#missing[@]} apt packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "[install_deps] apt packages: all ${#APT_PACKAGES[@]} present"
fi

# --- onnxruntime: library from the PyPI wheel, headers from Debian trixie ---------------
if [ -f "$ORT_DIR/lib/libonnxruntime.so.1" ] && [ -f "$ORT_DIR/include/onnxruntime_cxx_api.h" ] \
   && [ "$(cat "$ORT_DIR/VERSION" 2>/dev/null)" = "$ORT_VERSION" ]; then
  echo "[install_deps] onnxruntime $ORT_VERSION: present in $ORT_DIR"
else
  echo "[install_deps] fetching onnxruntime $ORT_VERSION into $ORT_DIR"
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' EXIT
  python3 -m pip --version >/dev/null 2>&1 || { echo "pip missing for python3" >&2; exit 1; }
  python3 -m pip download -q --no-deps --only-binary=:all: --platform manylinux_2_28_x86_64 \
      --python-version 3.11 -d "$work/wheel" "onnxruntime==$ORT_VERSION"
  whl="$(ls "$work"/wheel/onnxruntime-*.whl)"
  mkdir -p "$work/unz"
  unzip -q -o "$whl" 'onnxruntime/capi/libonnxruntime.so*' -d "$work/unz"
  lib="$(ls "$work"/unz/onnxruntime/capi/libonnxruntime.so.* | head -n1)"

  # Headers: trixie's libonnxruntime-dev fetched with a private apt state.
  mkdir -p "$work/apt/lists/partial" "$work/apt/cache/archives/partial" "$work/deb"
  echo 'deb [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian trixie main' \
      > "$work/apt/sources.list"
  apt_private=(-o Dir::Etc::sourcelist="$work/apt/sources.list" -o Dir::Etc::sourceparts=-
               -o Dir::State::lists="$work/apt/lists" -o Dir::Cache="$work/apt/cache"
               -o Debug::NoLocking=1 -o APT::Sandbox::User=root)
  apt-get "${apt_private[@]}" update -qq
  (cd "$work/deb" && apt-get "${apt_private[@]}" download libonnxruntime-dev)
  mkdir -p "$work/x"
  dpkg -x "$work"/deb/libonnxruntime-dev_*.deb "$work/x"

  rm -rf "$ORT_DIR"
  mkdir -p "$ORT_DIR/lib" "$ORT_DIR/include"
  cp "$lib" "$ORT_DIR/lib/"
  ln -sf "$(basename "$lib")" "$ORT_DIR/lib/libonnxruntime.so.1"
  ln -sf libonnxruntime.so.1 "$ORT_DIR/lib/libonnxruntime.so"
  hdr="$(dirname "$(find "$work/x" -name onnxruntime_cxx_api.h | head -n1)")"
  cp -r "$hdr"/. "$ORT_DIR/include/"
  echo "$ORT_VERSION" > "$ORT_DIR/VERSION"
  echo "[install_deps] onnxruntime $ORT_VERSION installed"
fi
echo "[install_deps] done"
