#!/usr/bin/env bash
# The look-alike guard's per-update search budget on a map the project never saw: the seeded
# method on the trials of scripts/bench_new_map.sh (same world file, models, seed, 30 trials,
# 10 updates), once with every search run whole (the library's default) and once with at most
# 500,000 nodes of search per update (--guard-nodes-per-update, the ROS node's default), one
# after the other. Writes OUT/REPORT.md (scripts/guard_budget_report.py's table) and each run's
# trials.csv / updates.csv under OUT/<name>/. Run scripts/bench_new_map.sh first: it writes the
# world file and trains the models (~7 min on 2 cores for Willow).
# Usage: scripts/bench_new_map_guard_budget.sh NAME [OUT]   (e.g. willow; default OUT:
#        reports/new_map/NAME/guard_per_update)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
name="${1:?usage: $0 NAME [OUT]}"
out="${2:-reports/new_map/$name/guard_per_update}"
models="out/models/$name"
world="$models/$name.world.yaml"
[[ -f "$world" ]] || { echo "$world not found: run scripts/bench_new_map.sh for '$name' first" >&2; exit 2; }
commands=()
for setting in 4M_default 4M_500k_per_update; do
  per_update=0
  [[ $setting == 4M_500k_per_update ]] && per_update=500000
  cmd=(./build/mrpt_krp_plugin/apps/krp-bench --worlds "$world" --models-for "$name=$models" --methods seeded
       --trials "${TRIALS:-30}" --steps 10 --seed "${SEED:-1}" --guard-nodes-per-update "$per_update"
       --out "$out/$name/$setting")
  echo "== $name, $setting"
  "${cmd[@]}" >/dev/null
  rm -f "$out/$name/$setting"/*.png
  commands+=("$name, $setting: \`${cmd[*]}\`")
done
python3 scripts/guard_budget_report.py --made-by "scripts/bench_new_map_guard_budget.sh $name" "$out" "$out/REPORT.md" \
  "${commands[@]}"
cat "$out/REPORT.md"
