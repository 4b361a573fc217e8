#!/usr/bin/env bash
# Installs strata's build dependencies from Debian 12's packages when they are missing, and the
# view page's packages from package-lock.json (npm ci) when node_modules/ does not match it.
# Usage: scripts/setup.sh [test | coverage | docs]
#   test: also clang with its sanitizer and libFuzzer runtimes (the `asan` preset the test
#         command builds), Debian's chromium (the browser tests of the view page) and
#         assimp-utils (the reference reader of tests/corpus/assimp_agreement_test.cpp), and
#         slurm-wlm, munge and iproute2 (tests/slurm/ starts a one-node Slurm cluster; `ss`
#         finds its free ports), and time (GNU time: peak memory in tests/scale/)
#   coverage: the same, and llvm-profdata-14 and llvm-cov-14 (scripts/coverage.sh)
#   docs: doxygen, for the API documentation (the target strata_docs)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake ninja-build pkg-config
  help2man dpkg-dev  # the man page from --help; dpkg-shlibdeps for `cpack -G DEB`
  libcgal-dev libboost-dev libgmp-dev libmpfr-dev libtbb-dev
  libpng-dev zlib1g-dev libfmt-dev nlohmann-json3-dev libcli11-dev lib3mf-dev
  libgtest-dev libgmock-dev libbenchmark-dev
)
case "${1:-}" in
  test | sanitizers | coverage)
    # Debian 12: clang 14; the ASan, UBSan and libFuzzer runtimes are in libclang-rt-14-dev.
    packages+=(clang libclang-rt-14-dev chromium assimp-utils slurm-wlm munge iproute2 time)
    ;;&
  coverage)
    # The profile runtime is in libclang-rt-14-dev too; the tools that read profiles in llvm-14.
    packages+=(llvm-14 python3)
    ;;
  docs)
    packages+=(doxygen)
    ;;
esac
# Node.js bundles the view page at build time; a machine that has a node already keeps it.
command -v node > /dev/null || packages+=(nodejs)
command -v npm > /dev/null || packages+=(npm)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
if ((${#missing[@]})); then
  echo "strata setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The page's packages (three.js, uPlot, esbuild, playwright-core), exactly as the lock file pins
# them; nothing is fetched when node_modules/ already matches it.
lock_sum="$(sha256sum package-lock.json | cut -d' ' -f1)"
if [ "$(cat node_modules/.strata-lock-sum 2>/dev/null)" != "$lock_sum" ]; then
  echo "strata setup: npm ci (the view page's packages)"
  npm ci --no-audit --no-fund --loglevel=error
  echo "$lock_sum" > node_modules/.strata-lock-sum
fi
