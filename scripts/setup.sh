#!/usr/bin/env bash
# Installs strata's build dependencies from Debian 12's packages when they are missing.
# Usage: scripts/setup.sh [sanitizers]   (`sanitizers` adds clang and its sanitizer and libFuzzer
# runtimes, for the `asan` preset)
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libcgal-dev libboost-dev libgmp-dev libmpfr-dev libtbb-dev
  libpng-dev zlib1g-dev libfmt-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
)
if [ "${1:-}" = sanitizers ]; then
  # Debian 12: clang 14; the ASan, UBSan and libFuzzer runtimes are in libclang-rt-14-dev.
  packages+=(clang libclang-rt-14-dev)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "strata setup: installing ${missing[*]}"
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
