#!/usr/bin/env bash
# Pins scripts/trace_root_order.sh: bad arguments and an existing output folder are refused before
# anything runs, and a real trace (office_two_zone, trial 0, the first scan only) prints the
# first scan's hypotheses in both root orders, the matcher's at full precision. The search is
# exact, so both orders must print the same matcher scores (their places may differ on a tie).
set -euo pipefail
root="${1:?usage: $0 REPO_ROOT}"
script="$root/scripts/trace_root_order.sh"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
office=(sim_worlds/office_two_zone/office_two_zone.yaml models/office_two_zone
        sim_worlds/office_two_zone/office_two_zone.zones.yaml)
for bad in "" "$work/a 0" "$work/b x ${office[*]} -- --trials 1" "$work/c 0 ${office[*]} --trials 1"; do
  # shellcheck disable=SC2086  # word splitting is the point: each is an argument list
  if "$script" $bad >/dev/null 2>&1; then echo "accepted: '$bad'"; exit 1; fi
done
mkdir "$work/exists"
if "$script" "$work/exists" 0 "${office[@]}" -- --trials 1 >/dev/null 2>&1; then
  echo "an existing output folder was accepted"; exit 1
fi
out="$("$script" "$work/trace" 0 "${office[@]}" -- --worlds office_two_zone --lidars omni_12m --methods seeded \
  --models-root models --trials 1 --steps 0 --seed 1)"
echo "$out"
for want in "first scan, roots across:" "first scan, roots heading after heading:" "  across " "  heading_after_heading "; do
  grep -qF -- "$want" <<< "$out" || { echo "missing: '$want'"; exit 1; }
done
scores() { sed -n "/roots $1:/,/^first scan/p" <<< "$out" | grep -oE 'score 0\.[0-9]+' | sort; }
across="$(scores across)"
before="$(scores "heading after heading")"
[[ -n "$across" ]] || { echo "no matcher hypothesis with a score"; exit 1; }
grep -qE 'score 0\.[0-9]{12,}' <<< "$across" || { echo "a matcher score is not at full precision"; exit 1; }
[[ "$across" == "$before" ]] || { echo "the two root orders scored differently"; exit 1; }
echo "trace_root_order: checks passed"
