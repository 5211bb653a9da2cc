#!/usr/bin/env bash
# Reruns every committed report that reads a world's shipped models (models/<world>), after those
# models were replaced: shipping new models means every figure made with the old ones is made
# again, or says which models it used. The list is kept here, beside the reports' own scripts,
# so that it is one place to grow when a report starts using the models.
#   scripts/rerun_model_reports.sh office_two_zone      (or warehouse, or all)
#   scripts/rerun_model_reports.sh --list warehouse     (print the commands, run nothing; --list
#                                                        may come after the world too)
# Several scripts cover both worlds in one run (their trial seeds depend on a world's place in the
# run); they run once. Hours on 2 cores: the scripts' headers give each one's time.
# (build first with scripts/build.sh; KRP_SKIP_SETUP=1 is passed to the recheck)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
usage="usage: $0 [--list] office_two_zone|warehouse|all"
# Hours of reruns that overwrite committed reports: anything but exactly one world and an
# optional --list (in either place) is refused before one of them starts.
list_only=0
which=""
for arg in "$@"; do
  case "$arg" in
    --list) list_only=1 ;;
    office_two_zone|warehouse|all)
      [[ -z "$which" ]] || { echo "$0: one world only, got '$which' and '$arg'" >&2; echo "$usage" >&2; exit 2; }
      which="$arg" ;;
    *) echo "$0: unknown argument '$arg'" >&2; echo "$usage" >&2; exit 2 ;;
  esac
done
[[ -n "$which" ]] || { echo "$usage" >&2; exit 2; }

commands=()
add() { commands+=("$*"); }
for_world() { [[ "$which" == all || "$which" == "$1" ]]; }
if for_world office_two_zone; then
  add scripts/bench_relocalization.sh office
  add scripts/bench_thesis_tables.sh office
  add scripts/bench_clutter.sh
  add scripts/bench_fresh_seeds.sh
  add scripts/bench_unseen_zone.sh
  add scripts/bench_watch_rejected.sh
  add scripts/bench_spread_count.sh office
  add scripts/bench_later_scans.sh office
  add KRP_SKIP_SETUP=1 scripts/krp-recheck-models --models models/office_two_zone --seed 2
  add KRP_SKIP_SETUP=1 scripts/krp-recheck-models --models models/office_two_zone --seed 3
fi
if for_world warehouse; then
  add scripts/bench_relocalization.sh warehouse
  add scripts/bench_relocalization.sh warehouse-40
  add scripts/bench_thesis_tables.sh warehouse
  add scripts/bench_spread_count.sh warehouse
  add scripts/bench_later_scans.sh warehouse
  add KRP_SKIP_SETUP=1 scripts/krp-recheck-models --models models/warehouse --seed 2
  add KRP_SKIP_SETUP=1 scripts/krp-recheck-models --models models/warehouse --seed 3
fi
# Both worlds in one run each.
add scripts/bench_calibration.sh learned
add scripts/bench_first_scan_verdict.sh
add scripts/bench_kidnap.sh
add scripts/bench_guard_budget.sh
add scripts/bench_scaling.sh

for c in "${commands[@]}"; do
  echo "$c"
  if [[ $list_only == 0 ]]; then bash -c "$c"; fi
done
