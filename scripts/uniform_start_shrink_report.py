#!/usr/bin/env python3
"""Writes the REPORT.md of scripts/bench_uniform_start_shrink.sh: the seeded method on the same
trials with a uniform start that keeps its count (fixed) and one that shrinks by KLD sampling
once converged (kld, the default).

Usage: uniform_start_shrink_report.py RUNS_DIR REPORT.md MADE_BY COMMAND_LINE...
RUNS_DIR holds fixed/ and kld/, each with krp-bench's trials.csv and updates.csv.
"""
import statistics
import sys
from pathlib import Path

from bench_csv import OUTCOME, percent, read

SETTINGS = (("fixed", "keeps its count (--seeded-uniform-start-fixed)"), ("kld", "shrinks by KLD sampling (default)"))


def median(values, fmt):
    return fmt.format(statistics.median(values)) if values else "-"


def summary(run_dir):
    trials = [t for t in read(run_dir / "trials.csv") if t["method"] == "seeded"]
    updates = [u for u in read(run_dir / "updates.csv") if u["method"] == "seeded"]
    # No hypothesis from the relocalizer: the filter started uniform.
    uniform = {t["trial"] for t in trials if int(t["seed_hypotheses"]) == 0}
    by_trial = {}
    for u in updates:
        by_trial.setdefault(u["trial"], []).append(u)
    first_particles, last_particles, late_cpu, total_cpu = [], [], [], []
    for trial in sorted(uniform, key=int):
        rows = sorted(by_trial[trial], key=lambda u: int(u["update"]))
        first_particles.append(int(float(rows[0]["particles"])))
        last_particles.append(int(float(rows[-1]["particles"])))
        # The tracking after the start: every update but the first, whose cost is the start's.
        late_cpu.extend(float(u["cpu_s"]) for u in rows[1:])
        total_cpu.append(sum(float(u["cpu_s"]) for u in rows))
    return {
        "trials": trials,
        "uniform": uniform,
        "first_particles": first_particles,
        "last_particles": last_particles,
        "late_cpu": late_cpu,
        "total_cpu": total_cpu,
    }


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    runs, report, made_by, commands = Path(sys.argv[1]), Path(sys.argv[2]), sys.argv[3], sys.argv[4:]
    s = {name: summary(runs / name) for name, _ in SETTINGS}
    lines = [
        "# A uniform start that shrinks once converged",
        "",
        f"Made by `{made_by}`: the `seeded` method on the same simulated trials twice, one run after the",
        "other. When the relocalizer has no hypothesis the filter starts as uniform MCL over the map's free",
        "space; with `fixed` it keeps that count to the end, with `kld` it sizes its set by KLD sampling",
        "(amcl's epsilon 0.01, z 0.99, 0.5 m / 10 deg bins) at each resampling once the weighted set has",
        "been concentrated (0.5 m, 10 deg) at 5 resamplings in a row (KldResamplingParams::",
        "concentrated_resamplings), never below the seeded floor (500) nor above the start's count.",
        "Trials the relocalizer seeded run the same code in both settings.",
        "",
        "Commands:",
        "",
    ]
    lines += [f"- {c}" for c in commands]
    lines += [
        "",
        "| uniform start | trials | success | confident-wrong | confident-right | trials started uniform | their particles at the start / last update (median) | their CPU per update after the first (median s) | their CPU per trial (median s) |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for name, label in SETTINGS:
        r = s[name]
        n = len(r["trials"])
        counts = [sum(int(t[k]) for t in r["trials"]) for k in OUTCOME]
        lines.append(
            f"| {label} | {n} | {percent(counts[0], n)} | {percent(counts[1], n)} | {percent(counts[2], n)} | "
            f"{len(r['uniform'])} | {median(r['first_particles'], '{:.0f}')} / {median(r['last_particles'], '{:.0f}')} | {median(r['late_cpu'], '{:.3f}')} | "
            f"{median(r['total_cpu'], '{:.2f}')} |"
        )
    fixed = {t["trial"]: t for t in s["fixed"]["trials"]}
    changed = [t["trial"] for t in s["kld"]["trials"] if any(t[k] != fixed[t["trial"]][k] for k in OUTCOME)]
    seeded_changed = [
        t["trial"]
        for t in s["kld"]["trials"]
        if t["trial"] not in s["kld"]["uniform"]
        and any(t[k] != fixed[t["trial"]][k] for k in OUTCOME + ("final_error_xy_m", "updates_to_convergence"))
    ]
    fixed_cpu, kld_cpu = s["fixed"]["late_cpu"], s["kld"]["late_cpu"]
    lines += [""]
    if fixed_cpu and kld_cpu:
        lines.append(
            f"Median CPU per update after the first, uniform-start trials: kld / fixed = "
            f"{statistics.median(kld_cpu) / statistics.median(fixed_cpu):.3f} (same trials, one run after the other)."
        )
    lines += [
        f"Trials whose outcome (converged, confident-wrong, confident-right) differs: {len(changed)}"
        + (f" ({', '.join(changed)})" if changed else "")
        + ".",
        f"Seeded trials whose outcome, final error or updates to convergence differ: {len(seeded_changed)}"
        + (f" ({', '.join(seeded_changed)})" if seeded_changed else "")
        + " (they run the same code; any difference would be a defect).",
        "",
    ]
    report.write_text("\n".join(lines))


if __name__ == "__main__":
    main()
