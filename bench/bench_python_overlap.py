#!/usr/bin/env python3
"""Overlap of many ellipse pairs from Python: ellipse_collision.core's batch form beside what a
Python user would otherwise write, shapely polygons of 64 vertices each and `intersects` in a
Python loop (and the core's scalar overlap() in a Python loop, the cost of the interpreter).

Times are CPU times (time.process_time), medians of repetitions that alternate the methods, so
that they share the machine's noise within one run. Misclassifications are counted on pairs
placed near tangency (t* = 1 -+ delta) and labelled by the 40-digit oracle
(test/support/contact_scale_oracle.py); the polygon's vertices lie on the rim, as a user's
`Point(0, 0).buffer(1, 16)` scaled and rotated would.

Then one fixed set of 10,000 obstacles asked about 1,000 robot-sized queries: core.EllipseBatch
(prepared once, far ellipses culled in SIMD registers) beside overlap_batch per query.

usage: bench_python_overlap.py [--pairs N] [--repetitions R] [--tangent-pairs K]
Run in the workspace's environment (source build/ws/devel/setup.bash; scripts/benchmark.sh does).
"""
import argparse
import math
import os
import random
import statistics
import sys
import time

import numpy
from shapely.geometry import Polygon

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "test",
                                "support"))
import contact_scale_oracle  # noqa: E402

from ellipse_collision import core  # noqa: E402

VERTICES = 64


def random_pairs(generator, count):
    """(count, 5) float64 arrays a and b: radii 0.05..2 m, axis ratios up to 10, centres of a
    within a 6 m square, b's within 1 m of a's along each axis (about a third overlap)."""
    def rows(x, y):
        radius_x = numpy.exp(generator.uniform(math.log(0.05), math.log(2.0), count))
        radius_y = radius_x / numpy.exp(generator.uniform(0.0, math.log(10.0), count))
        return numpy.column_stack([x, y, radius_x, radius_y,
                                   generator.uniform(-math.pi, math.pi, count)])
    a = rows(generator.uniform(-3, 3, count), generator.uniform(-3, 3, count))
    b = rows(a[:, 0] + generator.uniform(-1, 1, count), a[:, 1] + generator.uniform(-1, 1, count))
    return a, b


def polygons(rows):
    """One shapely Polygon per row, its VERTICES vertices on the ellipse's rim."""
    theta = numpy.linspace(0.0, 2.0 * math.pi, VERTICES, endpoint=False)
    unit = numpy.column_stack([numpy.cos(theta), numpy.sin(theta)])
    out = []
    for x, y, radius_x, radius_y, angle in rows:
        c, s = math.cos(angle), math.sin(angle)
        local = unit * (radius_x, radius_y)
        out.append(Polygon(numpy.column_stack([x + c * local[:, 0] - s * local[:, 1],
                                               y + s * local[:, 0] + c * local[:, 1]])))
    return out


def shapely_overlap(polygons_a, polygons_b):
    return numpy.array([p.intersects(q) for p, q in zip(polygons_a, polygons_b)])


def scalar_overlap(a, b):
    overlap = core.overlap
    ellipse = core.Ellipse
    return numpy.array([overlap(ellipse(*ra), ellipse(*rb)) for ra, rb in zip(a.tolist(),
                                                                              b.tolist())])


def cpu_seconds(function, *args):
    start = time.process_time()
    result = function(*args)
    return time.process_time() - start, result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--pairs", type=int, default=1000000)
    parser.add_argument("--repetitions", type=int, default=5)
    parser.add_argument("--tangent-pairs", type=int, default=100,
                        help="near-tangent pairs per delta and side")
    args = parser.parse_args()

    generator = numpy.random.default_rng(2024)
    a, b = random_pairs(generator, args.pairs)
    build_seconds, (polygons_a, polygons_b) = cpu_seconds(lambda: (polygons(a), polygons(b)))

    times = {"batch": [], "scalar": [], "shapely": []}
    answers = {}
    for _ in range(args.repetitions):
        for name, function, inputs in (("batch", core.overlap_batch, (a, b)),
                                       ("shapely", shapely_overlap, (polygons_a, polygons_b)),
                                       ("scalar", scalar_overlap, (a, b))):
            seconds, answers[name] = cpu_seconds(function, *inputs)
            times[name].append(seconds)
    assert (answers["scalar"] == answers["batch"]).all()
    batch = statistics.median(times["batch"])

    print("Overlap of %d pairs from Python (%.1f %% overlapping), CPU time, median of %d runs"
          % (args.pairs, 100.0 * answers["batch"].mean(), args.repetitions))
    print("%-52s %10s %12s %10s" % ("method", "total [s]", "ns per pair", "vs batch"))
    for name, label in (("batch", "core.overlap_batch (numpy arrays, loop in C++)"),
                        ("scalar", "core.overlap, Python loop over Ellipse objects"),
                        ("shapely", "shapely %d-gon intersects, Python loop" % VERTICES)):
        median = statistics.median(times[name])
        print("%-52s %10.3f %12.1f %10.1f" % (label, median, 1e9 * median / args.pairs,
                                                median / batch))
    print("%-52s %10.3f %12.1f   (once, not in the rows above)"
          % ("  building the %d shapely polygons" % (2 * args.pairs), build_seconds,
             1e9 * build_seconds / args.pairs))
    disagree = numpy.flatnonzero(answers["shapely"] != answers["batch"])
    oracle_sides_with_core = sum(contact_scale_oracle.overlaps(a[i], b[i]) == answers["batch"][i]
                                 for i in disagree)
    print("shapely and the core disagree on %d of the %d pairs (shapely says apart on %d); the "
          "oracle agrees with the core on %d of them"
          % (len(disagree), args.pairs, int((~answers["shapely"][disagree]).sum()),
             oracle_sides_with_core))

    print()
    print("Near tangency: pairs placed at t* = 1 -+ delta, labelled by the 40-digit oracle;")
    print("misclassified pairs of %d per row" % args.tangent_pairs)
    print("%-32s %8s %8s" % ("pairs", "core", "shapely"))
    rng = random.Random(5)
    for delta in (1e-3, 1e-6, 1e-9):
        for side, what in ((-1, "overlapping"), (1, "apart")):
            pairs = contact_scale_oracle.near_tangent_pairs(rng, args.tangent_pairs, delta, side)
            truth = numpy.array([bool(p[2] <= 1) for p in pairs])
            ta = numpy.array([p[0] for p in pairs])
            tb = numpy.array([p[1] for p in pairs])
            core_wrong = int((core.overlap_batch(ta, tb) != truth).sum())
            shapely_wrong = int((shapely_overlap(polygons(ta), polygons(tb)) != truth).sum())
            print("%-32s %8d %8d" % ("t* = 1 %s %g (%s)" % ("-" if side < 0 else "+", delta, what),
                                     core_wrong, shapely_wrong))

    fixed_set(args.repetitions)


def fixed_set(repetitions, obstacles=10000, queries=1000):
    """Many questions against one set (a map's obstacles against candidate robot poses):
    core.EllipseBatch, built once, beside overlap_batch on the query repeated against the set,
    which prepares the set anew on every call."""
    generator = numpy.random.default_rng(2025)
    # Obstacles 0.05..1 m over a 100 m x 100 m floor; robot-sized queries anywhere on it.
    radius_x = numpy.exp(generator.uniform(math.log(0.05), math.log(1.0), obstacles))
    rows = numpy.column_stack([generator.uniform(-50, 50, obstacles),
                               generator.uniform(-50, 50, obstacles), radius_x,
                               radius_x / generator.uniform(1.0, 5.0, obstacles),
                               generator.uniform(-math.pi, math.pi, obstacles)])
    query_rows = numpy.column_stack([generator.uniform(-50, 50, queries),
                                     generator.uniform(-50, 50, queries),
                                     numpy.full(queries, 0.5), numpy.full(queries, 0.3),
                                     generator.uniform(-math.pi, math.pi, queries)])
    query_ellipses = [core.Ellipse(*row) for row in query_rows.tolist()]
    build_seconds, batch = cpu_seconds(core.EllipseBatch, rows)

    def with_batch():
        return [batch.overlap_with(q) for q in query_ellipses]

    def with_overlap_batch():
        return [core.overlap_batch(numpy.broadcast_to(q, rows.shape), rows) for q in query_rows]

    times = {"set": [], "pairs": []}
    for _ in range(repetitions):
        for name, function in (("set", with_batch), ("pairs", with_overlap_batch)):
            seconds, answers = cpu_seconds(function)
            times[name].append(seconds)
            if name == "set":
                expected = answers
            else:
                assert all((x == y).all() for x, y in zip(expected, answers))
    pairs = obstacles * queries
    hits = int(sum(x.sum() for x in expected))
    print()
    print("One set of %d obstacles, %d queries (%d overlapping pairs), CPU time, median of %d runs"
          % (obstacles, queries, hits, repetitions))
    print("%-52s %10s %12s %10s" % ("method", "total [s]", "ns per pair", "vs set"))
    base = statistics.median(times["set"])
    for name, label in (("set", "core.EllipseBatch(rows).overlap_with(query)"),
                        ("pairs", "core.overlap_batch(query repeated, rows)")):
        median = statistics.median(times[name])
        print("%-52s %10.3f %12.2f %10.2f" % (label, median, 1e9 * median / pairs, median / base))
    print("%-52s %10.3f %12.2f   (once, not in the rows above)"
          % ("  building the EllipseBatch", build_seconds, 1e9 * build_seconds / obstacles))


if __name__ == "__main__":
    main()
