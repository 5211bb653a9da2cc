#!/usr/bin/env bash
# The main job: installs what is missing, builds, then runs kidnapped-robot trials in the
# office_two_zone sim world and prints the comparison table: uniform MCL, AMCL-style KLD, MCL seeded
# by the learned relocalizer (shipped models/office_two_zone) and by the global correlative matcher.
# Extra arguments go to krp-bench (e.g. --trials 30 --worlds warehouse).
set -euo pipefail
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$REPO_ROOT/scripts/install_deps.sh"
bash "$REPO_ROOT/scripts/build.sh"
cd "$REPO_ROOT"
./build/mrpt_krp_plugin/apps/krp-bench --worlds office_two_zone --trials 10 \
  --methods uniform-mcl,amcl-kld,seeded,global-matcher --models-root models --out out/demo "$@"
