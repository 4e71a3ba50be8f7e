#!/usr/bin/env bash
# Installs the Debian bookworm packages pathref needs, only those missing (apt-get, as root).
# Usage: bash tools/deps.sh          what building the library and the CLI needs (tools/demo)
#        bash tools/deps.sh --test   that, plus what the tests need (tools/test: Catch2,
#                                    RapidCheck, clang + libFuzzer, Python with scikit-learn and
#                                    SciPy, pybind11, librsvg for the figure checks, ...)
# Safe to run again.
set -euo pipefail
PATHREF_PACKAGES=(cmake ninja-build g++
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev
  libfmt-dev nlohmann-json3-dev libcli11-dev libsvm-dev)
if [[ "${1:-}" == "--test" ]]; then
  PATHREF_PACKAGES+=(clang libclang-rt-14-dev python3 librapidcheck-dev catch2 libbenchmark-dev
    python3-sklearn python3-scipy parallel
    pybind11-dev python3-dev python3-numpy python3-pytest
    librsvg2-bin fonts-dejavu-core)
fi
missing=()
for p in "${PATHREF_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "pathref: installing missing packages: ${missing[*]}"
  if [[ $(id -u) -ne 0 ]]; then
    echo "pathref: need root to apt-get install ${missing[*]}" >&2
    exit 2
  fi
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
