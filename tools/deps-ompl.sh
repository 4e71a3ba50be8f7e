#!/usr/bin/env bash
# Opt-in: installs OMPL (Debian bookworm libompl-dev, OMPL 1.5) for the peer benchmark
# bench/ompl/srrt_ompl_peer.cpp (issue 14, docs/performance.md "OMPL as the peer"). NOT part of
# tools/deps.sh: CI neither installs nor builds it, and no pathref library depends on OMPL.
# Usage (root): bash tools/deps-ompl.sh
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get install -y --no-install-recommends libompl-dev libboost-filesystem-dev  # omplConfig.cmake links boost_filesystem
cat <<'MSG'
OMPL installed. Build and run the peer benchmark:
  cmake -S . -B build-ompl -G Ninja -DCMAKE_BUILD_TYPE=Release -DPATHREF_BENCHMARKS=ON -DPATHREF_OMPL_PEER=ON
  cmake --build build-ompl --target srrt_ompl_peer
  build-ompl/bench/srrt_ompl_peer 100 1
MSG
