#!/usr/bin/env bash
# Installs the Debian 12 packages ancfnet needs, only those missing. Idempotent and quiet when
# everything is already there. Usage: scripts/install-deps.sh [--bench] [--fuzz] [--video]
set -euo pipefail

packages=(build-essential cmake libeigen3-dev libyaml-cpp-dev libcli11-dev libfmt-dev
          nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev libsuitesparse-dev
          libspectra-dev libassimp-dev python3 python3-numpy python3-matplotlib python3-pil python3-yaml
          python3-dev python3-pytest pybind11-dev python3-pip python3-setuptools python3-wheel
          libboost-dev libopenmpi-dev openmpi-bin)
for arg in "$@"; do
  case "$arg" in
    --bench) packages+=(hyperfine time) ;;
    # clang with libFuzzer and the sanitizers' runtimes, and clang's OpenMP (make fuzz).
    --fuzz) packages+=(clang libclang-rt-14-dev libomp-dev) ;;
    # ffmpeg for MP4 movies (`ancfnet animate`, docs/plots.md; without it: GIF through Pillow).
    --video) packages+=(ffmpeg) ;;
    *) echo "install-deps.sh: unknown option '$arg' (expected --bench, --fuzz or --video)" >&2
       exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
echo "install-deps.sh: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq >/dev/null
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
