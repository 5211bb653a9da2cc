#!/usr/bin/env bash
# Traces one krp-bench trial whose first-scan answer changed with the matcher's roots across
# headings (commit 61986f2): replays the trial with today's root order and with the order before
# (krp-bench --matcher-heading-after-heading), then relocalizes its first scan both ways with
# krp-localize --single-scan and prints the hypotheses side by side with their correlative-search
# scores at full precision. The search is exact: a hypothesis that moved to another place with
# the same score is an exact tie that the two visiting orders broke differently.
# Usage: scripts/trace_root_order.sh OUT TRIAL MAP MODELS ZONES -- KRP_BENCH_FLAGS...
#   OUT: a new folder; TRIAL: the trial's index in the run the flags describe (--worlds, --lidars,
#   --seed, --trials, --models-* as in the report's command; one world and one seeded method);
#   MAP, MODELS, ZONES: the map YAML, models folder and zones.yaml krp-localize is to use.
# (a few seconds on 2 cores; build first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
usage="usage: $0 OUT TRIAL MAP MODELS ZONES -- KRP_BENCH_FLAGS..."
[[ $# -ge 6 && "$6" == "--" ]] || { echo "$usage" >&2; exit 2; }
out="$1" trial="$2" map="$3" models="$4" zones="$5"
shift 6
[[ "$trial" =~ ^[0-9]+$ ]] || { echo "$0: TRIAL must be a trial index, got '$trial'" >&2; exit 2; }
for f in "$map" "$zones" "$models/manifest.json"; do
  [[ -f "$f" ]] || { echo "$0: $f not found" >&2; exit 2; }
done
[[ ! -e "$out" ]] || { echo "$0: $out exists: give a new folder" >&2; exit 2; }
bin=./build/mrpt_krp_plugin/apps
mkdir -p "$out"

# Each order replays the trial (its rawlog: the same scan either way) and relocalizes its first scan.
for order in across heading_after_heading; do
  bench_flags=() roots=1
  [[ "$order" == heading_after_heading ]] && bench_flags=(--matcher-heading-after-heading) roots=0
  "$bin/krp-bench" "$@" "${bench_flags[@]}" --only-trials "$trial" --save-rawlogs --out "$out/bench_$order" \
    > "$out/bench_$order.log" 2>&1
  rawlog="$(ls "$out/bench_$order"/rawlogs/*_trial"$trial".rawlog)"
  "$bin/krp-localize" --map "$map" --rawlog "$rawlog" --ground-truth "${rawlog%.rawlog}_groundtruth.txt" \
    --method seeded --models "$models" --zones "$zones" --single-scan 0 --matcher-roots-across-headings "$roots" \
    --out-dir "$out/single_scan_$order" > "$out/single_scan_$order.txt" 2>&1
done

python3 - "$out" <<'EOF'
import csv, json, sys
out = sys.argv[1]
print("trial rows of krp-bench (method, first-scan confidence, best error m, final error m):")
for order in ("across", "heading_after_heading"):
    for r in csv.DictReader(open(f"{out}/bench_{order}/trials.csv")):
        print(f"  {order:22s} {r['method']:16s} {r['seed_best_confidence']:>10s} {r['seed_best_error_xy_m']:>10s} "
              f"{r['final_error_xy_m']:>10s}")
for order in ("across", "heading_after_heading"):
    h = json.load(open(f"{out}/single_scan_{order}/hypotheses.json"))
    print(f"first scan, roots {order.replace('_', ' ')}: {'localized' if h['localized'] else 'not localized'}")
    for x in h["hypotheses"]:
        score = "-" if x["matcher_score"] is None else repr(x["matcher_score"])
        print(f"  x {x['x_m']:8.3f} y {x['y_m']:8.3f} yaw {x['yaw_deg']:8.2f}  fit {x['fit_fraction']:.3f}  "
              f"confidence {x['confidence']:.4f}  {x['origin']:9s} score {score}")
EOF
