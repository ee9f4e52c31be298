#!/usr/bin/env python3
"""Prints the collision benchmarks' JSON output (Google Benchmark --benchmark_out) as tables.

Usage: benchmark_table.py PAIRS_JSON [SCENES_JSON]

Times are CPU times; with repetitions, the median of them. Ratios are taken within the one run.
"""

import json
import sys


def load_runs(path):
    """Maps run name -> benchmark entry: the median aggregate if there are repetitions."""
    with open(path) as f:
        entries = json.load(f)["benchmarks"]
    runs = {}
    for entry in entries:
        name = entry.get("run_name", entry["name"])
        if entry.get("run_type") == "aggregate":
            if entry.get("aggregate_name") == "median":
                runs[name] = entry
        elif name not in runs:
            runs[name] = entry
    return runs


def pair_table(runs):
    rows = {}  # (method, mix) -> entry
    for name, entry in runs.items():
        parts = name.split("/")
        if parts[0] != "pair":
            continue  # contact_scale/* has a table of its own
        _, method, mix = parts
        rows[(method, mix)] = entry
    # one-to-N in the order of N.
    one_to_many = sorted({mix for _, mix in rows if mix.startswith("one-to-")},
                         key=lambda mix: int(mix.rsplit("-", 1)[1]))
    mixes = ordered({mix for _, mix in rows},
                    ["scene-like", "near", "tangent", "random-pairs"] + one_to_many)
    # batch_*: overlapBatch() / overlapOneToMany() with the portable and the AVX2 culling.
    # scene-like: 50 links each against the same obstacles of a 10 m room; near: pairs within
    # 1.5x their bounding radii; tangent: within 1e-6 of touching; random-pairs: independent pairs
    # in a 20 m square; one-to-N: one ellipse against N in that square, one overlapOneToMany() call.
    # batch_built: the batch with its EllipseBatch filled anew in every call.
    methods = ["ours_overlap", "ours_prepared", "batch_portable", "batch_avx2", "batch_built",
               "eigenvalue_alone", "polygonal_alone", "fcl", "seed_readme"]
    print("Pair tests (same stored pairs per mix; misclassified = disagreements with the quad "
          "oracle, pairs within 1e-12 of tangency left out)")
    header = (f"{'method':<18} {'mix':<13} {'ns/pair':>9} {'x faster than FCL':>18} "
              f"{'misclassified':>14} {'Unknown->eigen':>15}")
    print(header)
    print("-" * len(header))
    for mix in mixes:
        fcl = rows.get(("fcl", mix))
        fcl_ns = fcl["sec_per_pair"] * 1e9 if fcl else None
        for method in methods:
            entry = rows.get((method, mix))
            if entry is None:
                continue
            ns = entry["sec_per_pair"] * 1e9
            ratio = f"{fcl_ns / ns:.1f}" if fcl_ns else "-"
            wrong = f"{int(entry['misclassified'])}/{int(entry['counted'])}"
            fallbacks = entry.get("unknown_fallbacks")
            fallbacks = f"{int(fallbacks)}" if fallbacks is not None else ""
            print(f"{method:<18} {mix:<13} {ns:>9.2f} {ratio:>18} {wrong:>14} {fallbacks:>15}")
        passing = int(fcl["pass_bounding"]) if fcl else 0
        counted = int(fcl["counted"]) if fcl else 0
        overlapping = f", {int(fcl['overlapping'])} overlapping" if fcl and "overlapping" in fcl else ""
        print(f"{'':<18} {mix:<13} ({passing} of {counted} pairs within their bounding "
              f"circles{overlapping})")
    caps = sorted({int(m.rsplit("_", 1)[1]) for m, _ in rows if m.startswith("cap_study_")})
    if caps:
        print()
        print("overlap() with polygonal iteration caps (ns/pair; the core uses "
              "kOverlapPolygonalIterations)")
        studied = [mix for mix in mixes if any(m.startswith("cap_study_") and x == mix
                                               for m, x in rows)]
        print(f"{'cap':>4} " + " ".join(f"{mix:>11}" for mix in studied))
        for cap in caps:
            cells = []
            for mix in studied:
                entry = rows.get((f"cap_study_{cap}", mix))
                cells.append(f"{entry['sec_per_pair'] * 1e9:>11.1f}" if entry else f"{'-':>11}")
            print(f"{cap:>4} " + " ".join(cells))


def scene_table(runs, family="scene"):
    rows = {}  # (method, obstacles) -> entry
    for name, entry in runs.items():
        prefix, method, obstacles = name.split("/")
        if prefix == family:
            rows[(method, int(obstacles))] = entry
    sizes = sorted({n for _, n in rows})
    methods = ordered({method for method, _ in rows},
                      ["brute_force", "grid_streamed", "grid_streamed_with_scale", "grid_batch",
                       "grid_tight_boxes", "grid_prepared", "sort_and_sweep", "checkScene",
                       "checkScene_vouched", "checkScene_warn", "indexed_obstacles",
                       "indexed_build"])
    where = {"scene": "50 m x 50 m", "crowded": "4 m x 4 m"}.get(family, family)
    print(f"Scene checks: 50 links vs N obstacles in {where}, plus link-link pairs, per cycle on "
          "one core")
    # x bare: time over grid_streamed (the bare broadphase + overlap(), same pairs) at the same N;
    # x +scale: over grid_streamed_with_scale (the same plus the colliding pairs' contact scales).
    header = (f"{'obstacles':>9} {'method':<24} {'us/cycle':>10} {'x bare':>7} {'x +scale':>8} "
              f"{'pair tests':>11} {'collisions':>10} {'growth vs N/10':>15}")
    print(header)
    print("-" * len(header))
    for n in sizes:
        for method in methods:
            entry = rows.get((method, n))
            if entry is None:
                continue
            us = to_microseconds(entry)
            previous = rows.get((method, n // 10))
            growth = f"{us / to_microseconds(previous):.1f}x" if previous else ""
            bare = rows.get(("grid_streamed", n))
            versus = f"{us / to_microseconds(bare):.2f}" if bare else "-"
            scaled = rows.get(("grid_streamed_with_scale", n))
            versus_scaled = f"{us / to_microseconds(scaled):.2f}" if scaled else "-"
            # indexed_build builds the grid and tests no pair.
            pair_tests = f"{int(entry['pair_tests'])}" if "pair_tests" in entry else "-"
            collisions = f"{int(entry['collisions'])}" if "collisions" in entry else "-"
            print(f"{n:>9} {method:<24} {us:>10.1f} {versus:>7} {versus_scaled:>8} "
                  f"{pair_tests:>11} {collisions:>10} {growth:>15}")


def ordered(names, preferred):
    """`names` in the order of `preferred`, any others after them alphabetically."""
    return [n for n in preferred if n in names] + sorted(n for n in names if n not in preferred)


def to_microseconds(entry):
    scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}[entry["time_unit"]]
    return entry["cpu_time"] * scale


def contact_scale_table(runs):
    rows = {name.split("/", 1)[1]: entry for name, entry in runs.items()
            if name.startswith("contact_scale/")}
    if not rows:
        return
    print("contactScale() on the colliding pairs of a robot scene (50 links, 100,000 obstacles)")
    header = f"{'variant':<24} {'ns/pair':>9} {'pairs':>7} {'steps':>7} {'fallbacks':>10}"
    print(header)
    print("-" * len(header))
    for name, entry in sorted(rows.items()):
        ns = entry["sec_per_pair"] * 1e9
        pairs = int(entry.get("pairs", 0))
        steps = entry.get("quartic_steps", 0.0)
        fallbacks = int(entry.get("fallbacks", 0))
        print(f"{name:<24} {ns:>9.1f} {pairs:>7} {steps:>7.2f} {fallbacks:>10}")


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    pair_runs = load_runs(sys.argv[1])
    pair_table(pair_runs)
    print()
    contact_scale_table(pair_runs)
    if len(sys.argv) == 2:
        return
    print()
    scene_runs = load_runs(sys.argv[2])
    scene_table(scene_runs)
    print()
    scene_table(scene_runs, "crowded")


if __name__ == "__main__":
    main()
