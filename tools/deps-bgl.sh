#!/usr/bin/env bash
# Opt-in: installs the Boost Graph Library (Debian bookworm libboost-graph-dev, Boost 1.74) for the
# peer benchmark bench/bgl/astar_bgl_peer.cpp (issue 18, docs/performance.md "BGL as the peer").
# NOT part of tools/deps.sh: CI neither installs nor builds it, and no pathref library depends on
# Boost. Usage (root): bash tools/deps-bgl.sh
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get install -y --no-install-recommends libboost-graph-dev
cat <<'MSG'
Boost.Graph installed. Build and run the peer benchmark (same flags as the measured build):
  cmake -S . -B build-bgl -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DPATHREF_BGL_PEER=ON
  cmake --build build-bgl --target astar_bgl_peer
  build-bgl/bench/astar_bgl_peer --reps 5 --every 10
MSG
