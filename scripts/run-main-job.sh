#!/usr/bin/env bash
# The main job: builds hbtrack and computes the nonlinear frequency response of the shipped
# examples, with figures, into results/. (The blade study replaces it once the blade exists.)
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j "$(nproc)"
mkdir -p results
for example in duffing two_dof_contact coupled_duffing chain_contact; do
  ./build/hbtrack frc "examples/$example.toml" -o "results/$example"
  /usr/bin/python3 python/plot_branch.py "results/$example"
done
echo "figures: results/*/nfrc.png"
