#!/usr/bin/env bash
# Regenerates reports/guard_budget (issue 4): what the look-alike guard does when its whole-map
# search runs out of its node budget (--guard-max-search-nodes) with nothing found, and which
# budget to default to. The guarded methods replay the same simulated kidnaps under each setting:
#   1M settled:    a budget of 1,000,000 nodes (the default before this report) with
#                  --guard-unverified-is-settled: an unfinished search counts as finding nothing
#                  (the guard before LookAlikeGuardParams::unverified_is_unsettled);
#   1M, 2M:        budgets of 1,000,000 and 2,000,000, a converged filter no search has yet checked
#                  in full reported unverified (its covariance widened);
#   4M (default):  the default budget, 4,000,000;
#   no limit:      --guard-max-search-nodes 0, every search exact, whatever it costs;
#   4M, 500k/250k per update: the default budget, each update scoring at most 500,000 (250,000)
#                  nodes of search (--guard-nodes-per-update): a longer search pauses and goes on
#                  at the next updates, so no update stalls (the ROS node's default is 500,000).
# Warehouse: 30 trials, every setting. Office (100 trials): 1M settled, the default and 500k per update.
# 360 deg 12 m lidar, 10 updates, seed 1, as reports/relocalization (~20 min on 2 idle cores).
# Usage: scripts/bench_guard_budget.sh   (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
bench=./build/mrpt_krp_plugin/apps/krp-bench
out=reports/guard_budget
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
methods=seeded,seeded-no-cross-check,global-matcher-guarded
declare -A flags=(
  [1M_settled]="--guard-max-search-nodes 1000000 --guard-unverified-is-settled"
  [1M]="--guard-max-search-nodes 1000000"
  [2M]="--guard-max-search-nodes 2000000"
  [4M_default]=""
  [no_limit]="--guard-max-search-nodes 0"
  [4M_500k_per_update]="--guard-nodes-per-update 500000"
  [4M_250k_per_update]="--guard-nodes-per-update 250000"
)
runs=(office_two_zone:1M_settled office_two_zone:4M_default office_two_zone:4M_500k_per_update
      warehouse:1M_settled warehouse:1M warehouse:2M warehouse:4M_default warehouse:no_limit
      warehouse:4M_500k_per_update warehouse:4M_250k_per_update)
commands=()
for run in "${runs[@]}"; do
  world="${run%%:*}" setting="${run#*:}"
  trials=30
  [[ "$world" == office_two_zone ]] && trials=100
  # shellcheck disable=SC2206  # the setting's flags are meant to split
  cmd=("$bench" --worlds "$world" --lidars omni_12m --models-root models --steps 10 --seed 1 --trials "$trials"
       --methods "$methods" ${flags[$setting]} --out "$work/$world/$setting")
  echo "== $world, $setting"
  "${cmd[@]}" >/dev/null
  commands+=("$world, $setting: \`${cmd[*]/#$work/OUT}\`")
done
mkdir -p "$out"
python3 scripts/guard_budget_report.py "$work" "$out/REPORT.md" "${commands[@]}"
cat "$out/REPORT.md"
