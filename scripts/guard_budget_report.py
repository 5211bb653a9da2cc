#!/usr/bin/env python3
"""Writes reports/guard_budget/REPORT.md from the krp-bench runs of scripts/bench_guard_budget.sh.

Usage: guard_budget_report.py [--made-by SCRIPT] RUNS_DIR REPORT.md COMMAND_LINE...
RUNS_DIR holds <world>/<setting>/{trials,updates}.csv; each world's 4M_default run is the one
the others are compared with. --made-by names the script that ran them (default: this report's).
"""
import statistics
import sys
from pathlib import Path

from bench_csv import OUTCOME, percent, read

SETTING_ORDER = ("1M_settled", "1M", "2M", "4M_default", "no_limit", "4M_500k_per_update", "4M_250k_per_update")
SETTING_NAMES = {
    "1M_settled": "1M, unfinished = settled (before)",
    "1M": "1M",
    "2M": "2M",
    "4M_default": "4M (default)",
    "no_limit": "no limit",
    "4M_500k_per_update": "4M, 500k per update",
    "4M_250k_per_update": "4M, 250k per update",
}
BASELINE = "4M_default"


def seconds(values, pick):
    return f"{pick(values):.2f}" if values else "-"


def rows_for(world_dir, setting, base):
    trials = read(world_dir / setting / "trials.csv")
    updates = read(world_dir / setting / "updates.csv")
    for method in dict.fromkeys(r["method"] for r in trials):
        t = [r for r in trials if r["method"] == method]
        u = [r for r in updates if r["method"] == method]
        searched = [float(r["look_alike_search_cpu_s"]) for r in u if int(r["look_alike_searches"]) > 0]
        n = len(t)
        differs = sum(any(r[k] != base[(method, r["trial"])][k] for k in OUTCOME) for r in t)
        yield (f"| {world_dir.name} | {SETTING_NAMES[setting]} | {method} | {n} "
               f"| {percent(sum(r['converged'] == '1' for r in t), n)} "
               f"| {percent(sum(r['confident_but_wrong'] == '1' for r in t), n)} "
               f"| {percent(sum(r['confident_and_right'] == '1' for r in t), n)} "
               f"| {sum(int(r['look_alike_searches']) for r in t)} "
               f"| {sum(int(r['look_alike_searches_unfinished']) for r in t)} "
               f"| {sum(r['look_alike_unverified'] == '1' for r in u)} of {len(u)} "
               f"| {sum(searched):.1f} | {seconds(searched, statistics.median)} | {seconds(searched, max)} "
               f"| {differs} |")


def main(argv):
    made_by = "scripts/bench_guard_budget.sh"
    if len(argv) > 2 and argv[1] == "--made-by":
        made_by, argv = argv[2], argv[:1] + argv[3:]
    if len(argv) < 3:
        sys.exit(__doc__)
    runs, report, commands = Path(argv[1]), Path(argv[2]), argv[3:]
    lines = [
        "# The look-alike guard out of budget",
        "",
        f"Made by `{made_by}`. The guard's whole-map search for a look-alike place "
        "scores at most `--guard-max-search-nodes` nodes. A search that runs out with nothing found has "
        "not ruled out a look-alike: the filter now reports itself *unverified* (covariance widened like "
        "an unsettled pose's, so not confident) until a search since it converged finishes. *1M, "
        "unfinished = settled* is the guard before that, at the budget it had (1,000,000 nodes, "
        "`--guard-unverified-is-settled`: it still counts and flags such updates, without widening). "
        "Outcomes are at the last update, as in `reports/relocalization`. \"Unfinished\": searches out "
        "of budget with nothing found; \"updates unverified\": updates at which the filter flagged itself "
        "so; search CPU: the guard's search thread CPU summed over the trials, and the median and "
        "largest per update that searched (one core; the runs went one after the other on a shared "
        "machine, so compare within a world); \"outcome differs\": trials whose converged / "
        "confident-but-wrong / confident-and-right differ from the same world's default run. "
        "*Per update*: `--guard-nodes-per-update N`, each filter update scores at most about N nodes of "
        "search; a search that needs more pauses and goes on at the next updates (the pose reads "
        "unverified meanwhile, and a place it finds is moved along the odometry since its scan), so "
        "\"searches\" counts each update's slice of one.",
        "",
        "| world | budget | method | trials | success | confident-wrong | confident-right | searches "
        "| unfinished | updates unverified | search CPU s, total | per update, median | max | outcome differs |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for world_dir in sorted(p for p in runs.iterdir() if p.is_dir()):
        base = {(r["method"], r["trial"]): r for r in read(world_dir / BASELINE / "trials.csv")}
        for setting in SETTING_ORDER:
            if (world_dir / setting / "trials.csv").exists():
                lines.extend(rows_for(world_dir, setting, base))
    temporary = any("OUT/" in c for c in commands)
    lines += ["", "Commands (OUT: a temporary folder):" if temporary else "Commands:", ""]
    lines += [f"- {c}" for c in commands] + [""]
    report.write_text("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv)
