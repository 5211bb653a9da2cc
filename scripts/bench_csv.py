"""What the report scripts beside it share: krp-bench's CSV files and their outcome columns."""
import csv

# trials.csv's outcome of a trial, each 0 or 1.
OUTCOME = ("converged", "confident_but_wrong", "confident_and_right")


def read(path):
    """A krp-bench CSV file (trials.csv, updates.csv) as a list of dicts."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def percent(count, total):
    return f"{100.0 * count / total:.3g} %" if total else "-"
