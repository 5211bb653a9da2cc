#!/usr/bin/env bash
# Regenerates reports/matcher_speed (issue 4): the correlative matcher's bounds that stop reading
# returns once a node cannot win, against bounds that read every return, side by side on the same
# simulated first scans (krp-bench-matcher; both must answer alike); then every heading against
# the wall-heading windows (MatchRequest::wall_heading_window_deg, the relocalizer's default: 3 deg;
# the 5 deg of before are compared with 3 in reports/heading_window), on the same scans; then
# the whole-map search's second solution searched from min_score against warm-started
# (CorrelativeMatcherParams::warm_start_later_solutions), on the same scans. Worlds office_two_zone,
# warehouse and large_floor with their default lidars, and, when ../shared/data holds it, the map
# of the Freiburg 101 log (its odd scans, as scripts/check_freiburg.sh builds it) with the log's
# SICK LMS profile (third-party data: only the numbers go into the report); the cluttered office
# and the office with the 3.5 m lds01 lidar as well. 50 scans each, seed 1 (~10 min on 2 cores).
# Usage: scripts/bench_matcher.sh [DATA_DIR]   (build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
bin=./build/mrpt_krp_plugin/apps
out=reports/matcher_speed
scans=50
for world in office_two_zone warehouse large_floor; do
  "$bin/krp-bench-matcher" --world "$world" --scans "$scans" --seed 1 --out "$out/$world"
done
# The scans least kind to the wall-heading windows: unmapped clutter, and the 3.5 m lidar.
"$bin/krp-bench-matcher" --world office_cluttered --scans "$scans" --seed 1 --out "$out/office_cluttered"
"$bin/krp-bench-matcher" --world office_two_zone --lidar lds01 --scans "$scans" --seed 1 --out "$out/office_two_zone_lds01"

log="${1:-../shared/data/freiburg-101}/freiburg-101-corrected.log.gz"
if [[ ! -f "$log" ]]; then
  echo "bench_matcher: $log not found: the Freiburg 101 map is left out" >&2
  exit 0
fi
work=out/bench_matcher_freiburg_101  # the map and the guard runs, kept for a look (out/ is not committed)
mkdir -p "$work"
"$bin/krp-map-from-log" --carmen "$log" --first 1 --every 2 --out "$work/freiburg_101_odd_scans.yaml"
"$bin/krp-bench-matcher" --map "$work/freiburg_101_odd_scans.yaml" --lidar scripts/sick_lms_freiburg.yaml \
  --scans "$scans" --seed 1 --out "$out/freiburg_101"

# How often the guard searches, on the real log: the guarded filter over the whole log with the
# look-alike search every 1, 3 and 5 updates (one run after the other).
recheck="$out/freiburg_101/GUARD_RECHECK.md"
{
  echo "# The look-alike guard's recheck interval over the Freiburg 101 log"
  echo
  echo "Made by scripts/bench_matcher.sh; one run after the other on one machine."
  echo
  echo "| --guard-recheck-every | localization CPU | look-alike searches, their CPU | converged | updates to convergence | median error | poses identical to every update |"
  echo "|---|---|---|---|---|---|---|"
} > "$recheck"
for every in 1 3 5; do
  run="$work/guard_recheck_$every"
  cmd=("$bin/krp-localize" --map "$work/freiburg_101_odd_scans.yaml" --carmen "$log" --truth-from-log 1
       --method global-matcher-guarded --guard-recheck-every "$every" --out-dir "$run")
  "${cmd[@]}" >/dev/null
  field() { sed -n "s/^$1: //p" "$run/krp_localize_SUMMARY.txt"; }
  same=yes
  cmp -s <(cut -d, -f1-4 "$work/guard_recheck_1/poses.csv") <(cut -d, -f1-4 "$run/poses.csv") || same=no
  searches="$(sed -n 's/^look-alike searches: \([0-9]*\), \([^ ]*\) s of that CPU.*/\1, \2 s/p' "$run/krp_localize_SUMMARY.txt")"
  echo "| $every | $(field 'localization CPU') | $searches | $(field converged) | $(field 'updates to convergence') | $(field 'median error') | $same |" >> "$recheck"
done
echo >> "$recheck"
echo "Command (N = 1, 3, 5): \`${cmd[*]}\`" | sed "s/--guard-recheck-every 5/--guard-recheck-every N/; s/guard_recheck_5/guard_recheck_N/" >> "$recheck"
cat "$recheck"
