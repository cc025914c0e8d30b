"""Merge the results of several score.py runs (different seeds) into one C++ mutation score.

    .venv/bin/python conform/cpp_mutants/merge_scores.py RUN.json [RUN.json ...] --out SCORE_JSON

Each run is a stratified random sample of the same population (universalmutator's mutants
of src/*.cpp and include/safestate/*.hpp), so their union is a larger sample of it.  A
mutant sampled by two runs counts once, with the later run's row (the later suite).
Survivor notes are re-read from equivalent.toml.  Every run's seed, size, passes, commit
and seconds are kept under `runs`.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from score import counts, equivalents, note, row_key  # noqa: E402

RUN_FIELDS = ("seed", "sample_requested", "sampled", "stillborn", "evaluated", "killed", "passes",
              "input_complete_stride", "budget_seconds", "seconds", "stopped_by_budget", "date", "commit")


def merge(docs: list[dict]) -> dict:
    """One result from several; the population fields (targets, generated) must agree."""
    first = docs[0]
    for d in docs[1:]:
        if (d["targets"], d["generated"]) != (first["targets"], first["generated"]):
            raise ValueError(f"runs of different populations: {d['generated']} mutants of {d['targets']} vs "
                             f"{first['generated']} of {first['targets']}")
    rows: dict[tuple[str, str, str], dict] = {}
    for d in docs:
        for r in d["mutants"]:
            rows[row_key(r)] = r
    justified = equivalents()
    merged = list(rows.values())
    for r in merged:
        if r["status"] == "survived":
            r["note"] = note(r, justified)
    total = sum(len(d["mutants"]) for d in docs)
    return {"tool": first["tool"], "targets": first["targets"], "generated": first["generated"],
            "generated_per_file": first["generated_per_file"],
            "runs": [{k: d.get(k) for k in RUN_FIELDS} for d in docs],
            "sampled_twice": total - len(merged),
            "seconds": round(sum(d.get("seconds") or 0 for d in docs), 1),
            "commit": docs[-1].get("commit"), "date": docs[-1].get("date"),
            **counts(merged), "mutants": merged}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", type=Path, nargs="+", help="score.json files written by score.py")
    ap.add_argument("--out", type=Path, required=True)
    a = ap.parse_args()
    docs = []
    for p in a.runs:
        try:
            docs.append(json.loads(p.read_text(encoding="utf-8")))
        except (OSError, json.JSONDecodeError) as e:
            print(f"error: {p}: not a readable score.json ({e})", file=sys.stderr)
            return 2
    try:
        d = merge(docs)
    except (KeyError, ValueError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    a.out.write_text(json.dumps(d, indent=1) + "\n", encoding="utf-8")
    print(f"C++ mutation score: {d['score_percent']}% ({d['killed']}/{d['evaluated']} killed, "
          f"{d['survived_equivalent']} equivalent; without them {d['score_without_equivalent_percent']}%, 95% "
          f"interval {d['confidence_95_percent_without_equivalent']}) from {len(docs)} runs -> {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
