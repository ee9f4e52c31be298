#!/usr/bin/python3
"""Writes the seed corpus test/fuzz_corpus/<target>/ of the fuzz targets in fuzz/.

Usage: fuzz/make_seeds.py [OUTPUT_DIR]   (default: test/fuzz_corpus next to this file's parent)
       fuzz/make_seeds.py --open-findings DIR   inputs that still break a target, one folder per
                                                target, to reproduce with build/fuzz/<target> FILE

The seeds are committed; rerun this after changing the input format of fuzz/fuzz_input.h or a
target's reading order, and commit the result. Each seed is a named scenario (hostile values,
tangent, contained, thin, far-away, concentric pairs, bad scenes, projections) so that a short CI
run starts from every interesting region instead of having to discover it. Inputs that broke a
target are kept in open_findings() until the code is fixed, then move into the seeds as
regression-* entries that every run replays.
"""

import math
import os
import struct
import sys

# Indices into hostileValues() in fuzz/fuzz_input.h.
HOSTILE = [
    "0",
    "-0",
    "1",
    "-1",
    "0.5",
    "2",
    "3",
    "10",
    "pi/2",
    "pi",
    "-pi",
    "2pi",
    "1e300",
    "-1e300",
    "1e-300",
    "-1e-300",
    "max",
    "-max",
    "min_normal",
    "-min_normal",
    "denorm_min",
    "-denorm_min",
    "largest_subnormal",
    "inf",
    "-inf",
    "nan",
    "-nan",
    "min_radius",
    "below_min_radius",
    "max_radius",
    "above_max_radius",
    "max_coordinate",
    "-max_coordinate",
    "above_max_coordinate",
    "1e-12",
    "1e12",
    "1e-6",
    "1e6",
    "1e18",
    "0.1",
]
assert len(HOSTILE) == 40


def special(name):
    """A value from the hostile table (tag 0)."""
    return bytes([0, HOSTILE.index(name)])


def num(value):
    """Any double, as its raw bits (tag 1)."""
    return bytes([1]) + struct.pack("<d", value)


def ulps(name, steps):
    """A hostile value moved by steps ulps (tag 2), -4 <= steps <= 4."""
    return bytes([2, HOSTILE.index(name), steps + 4])


def ellipse(cx, cy, rx, ry, angle):
    """Five numbers; each either a float or already-encoded bytes."""
    return b"".join(v if isinstance(v, bytes) else num(v) for v in (cx, cy, rx, ry, angle))


def byte(value):
    return bytes([value])


# ------------------------------------------------------------------------------- fuzz_core_pair
# Layout: ellipse a, ellipse b, shape (0 as given, 1 moved to tangency, 2 concentric,
# 3 congruent), polygonal iterations + 2.
def pair(a, b, shape=0, iterations=6):
    return a + b + byte(shape) + byte(iterations + 2)


def core_pair_seeds():
    unit = ellipse(0, 0, 1, 1, 0)
    seeds = {
        # Regressions (fixed): found by this fuzzer.
        # The polygonal test's rounding margin exceeds 1 for pairs spanning > 1e10 of the
        # smaller radius and then "proves" overlap of separate pairs (contact scale 1.07).
        "regression-polygonal-margin-above-one": pair(
            ellipse(0, 0, 100, 1e-9, 0), ellipse(0, 90, 100, 1e-9, 1.0)
        ),
        # polygonalTest certifies "separate" from 9 iterations on, yet the quad-precision oracle
        # gives t* = 0.99999997963 (overlap); overlap() is right only because it stops at 6.
        "regression-polygonal-false-separate": pair(
            ellipse(1e9, 3.0000000000000004, 3.0000000000000004, 2.9999999999999987, 1),
            ellipse(
                20.371089100837708, 6.111326733559963e-08, 1e9, 1e-9, -2.4983353906949635e-127
            ),
            iterations=20,
        ),
        # Nearly coincident centres: Q's slopes underflow and maximizeQ divides 0 by 0.
        "regression-eigenvalue-zero-slope-gap": pair(
            ellipse(0, 0, 1.0000000000000001e-09, 1e9, 0),
            ellipse(-2.237502219360062e-154, 7.9989294464120617e-315, 1e9, 1.030517578125, 0.5),
        ),
        "circles-overlap": pair(unit, ellipse(1, 0, 1, 1, 0)),
        "circles-clear": pair(unit, ellipse(3, 0, 1, 1, 0)),
        "circles-touching": pair(unit, ellipse(2, 0, 1, 1, 0)),
        "contained-tilted": pair(ellipse(0, 0, 3, 2, 0), ellipse(0.5, 0.2, 0.5, 0.25, 0.3)),
        "thin-vs-circle-clear": pair(ellipse(0, 0, 2, 0.1, 0), ellipse(0, 0.5, 0.3, 0.3, 0)),
        "thin-pointing-at-circle": pair(
            ellipse(0, 0, 2, 0.1, math.pi / 2), ellipse(0, 0.5, 0.3, 0.3, 0)
        ),
        "thin-crossing-t": pair(ellipse(0, 0, 2, 0.2, 0), ellipse(1.5, 1.5, 0.2, 2, 0)),
        "thin-parallel": pair(ellipse(0, 0, 2, 0.1, 0), ellipse(0, 0.5, 2, 0.1, 0), iterations=30),
        "ratio-1e3-tangent": pair(
            ellipse(0, 0, 1, 1e-3, 0.3), ellipse(0.5, 0.7, 2e-3, 2, -1.1), shape=1
        ),
        "ratio-1e9-tangent": pair(
            ellipse(0, 0, 10, 1e-8, 0.2), ellipse(1, 3, 1e-8, 10, 0), shape=1
        ),
        "far-from-origin": pair(
            ellipse(1e8, -1e8, 1, 0.5, 1), ellipse(1e8 + 1.2, -1e8 + 0.3, 0.4, 0.6, -2)
        ),
        "edge-of-ranges": pair(
            ellipse(
                special("max_coordinate"),
                special("-max_coordinate"),
                special("max_radius"),
                special("min_radius"),
                special("2pi"),
            ),
            ellipse(
                special("-max_coordinate"),
                special("max_coordinate"),
                special("min_radius"),
                special("max_radius"),
                special("-pi"),
            ),
        ),
        "tiny-and-huge": pair(
            ellipse(0, 0, special("min_radius"), special("min_radius"), 0),
            ellipse(3, 0, special("max_radius"), 1, 0.5),
            shape=1,
        ),
        "concentric": pair(ellipse(0.25, -4, 3, 0.5, 0.7), ellipse(7, 7, 0.5, 3, 0.1), shape=2),
        "congruent": pair(ellipse(0, 0, 1.5, 0.2, 0.4), ellipse(0.3, 0.1, 1, 1, -0.4), shape=3),
        "identical": pair(ellipse(1, 2, 3, 4, 5), ellipse(1, 2, 3, 4, 5)),
        "huge-angles": pair(
            ellipse(0, 0, 1, 0.5, special("1e300")), ellipse(1, 1, 1, 0.5, special("-max"))
        ),
        "iterations-out-of-range": pair(unit, ellipse(1.999, 0.001, 1, 0.999, 0.1), iterations=-2),
    }
    # Every field of a, in turn, set to each hostile value the core must refuse (or accept).
    fields = ["cx", "cy", "rx", "ry", "angle"]
    good = [0.5, -0.5, 1.0, 0.5, 0.25]
    for index, field in enumerate(fields):
        for name in (
            "nan",
            "-nan",
            "inf",
            "-inf",
            "1e300",
            "denorm_min",
            "0",
            "-0",
            "-1",
            "below_min_radius",
            "above_max_radius",
            "above_max_coordinate",
        ):
            values = list(good)
            values[index] = special(name)
            seeds["hostile-%s-%s" % (field, name)] = pair(ellipse(*values), ellipse(1, 0, 1, 1, 0))
    seeds["hostile-rx-min-radius-1ulp-below"] = pair(
        ellipse(0, 0, ulps("min_radius", -1), 1, 0), unit
    )
    seeds["hostile-cx-max-coordinate-1ulp-above"] = pair(
        ellipse(ulps("max_coordinate", 1), 0, 1, 1, 0), unit
    )
    return seeds


# ------------------------------------------------------------------------------- fuzz_scene
# Layout: flag (1 scene, 0 projection), then
#  scene: count, per entry (name index, role 0 query 1 link 2 obstacle, ellipse, clamp flag),
#         self_collision flag, allowed count + name index pairs, only-names count + indices,
#         warning-distance mode (0 none, 1 the number that follows), name for nearestTo();
#  projection: ellipse, translation (3 numbers), about-z flag, then angle or quaternion (w x y z).
NAMES = ["", "a", "b", "c", "d", "e", "f", "g", "h", "link/1", "obstacle 2"]


def entry(name, role, e, clamp=0):
    return byte(NAMES.index(name)) + byte(role) + e + byte(clamp)


def scene(entries, self_collision=1, allowed=(), only=(), warning=None, nearest=""):
    out = byte(1) + byte(len(entries)) + b"".join(entries) + byte(self_collision)
    out += byte(len(allowed)) + b"".join(
        byte(NAMES.index(x)) + byte(NAMES.index(y)) for x, y in allowed
    )
    out += byte(len(only)) + b"".join(byte(NAMES.index(x)) for x in only)
    # Warning distance: mode 0 none, 1 any number as given.
    out += (
        byte(0)
        if warning is None
        else byte(1) + (warning if isinstance(warning, bytes) else num(warning))
    )
    return out + byte(NAMES.index(nearest))


def projection(e, translation, angle=None, quaternion=None):
    out = byte(0) + e + b"".join(v if isinstance(v, bytes) else num(v) for v in translation)
    if angle is not None:
        return out + byte(1) + (angle if isinstance(angle, bytes) else num(angle))
    return out + byte(0) + b"".join(v if isinstance(v, bytes) else num(v) for v in quaternion)


def scene_seeds():
    link = lambda name, x, y: entry(name, 1, ellipse(x, y, 0.5, 0.2, 0.3))
    obstacle = lambda name, x, y: entry(name, 2, ellipse(x, y, 0.4, 0.4, 0))
    query = lambda name, x, y: entry(name, 0, ellipse(x, y, 0.3, 0.6, 1))
    arm = [
        link("a", 0, 0),
        link("b", 0.6, 0),
        link("c", 1.2, 0.1),
        obstacle("d", 1.0, 0.3),
        obstacle("e", 1.1, 0.4),
        query("f", 0.2, 0.1),
    ]
    angled = math.sqrt(0.5)
    return {
        "scene-empty": scene([]),
        "scene-arm": scene(arm, nearest="c"),
        "scene-arm-warnings": scene(arm, warning=0.3, nearest="f"),
        "scene-arm-hostile-warning": scene(arm, warning=special("nan")),
        "scene-arm-negative-warning": scene(arm, warning=-0.1),
        "scene-arm-no-self-collision": scene(arm, self_collision=0, warning=1.0, nearest="a"),
        "scene-arm-allowed": scene(arm, allowed=[("a", "b"), ("c", "d"), ("g", "a")], nearest="b"),
        "scene-arm-filter": scene(arm, only=["c", "h"], warning=10.0, nearest="e"),
        "scene-empty-name": scene([link("a", 0, 0), link("", 0.5, 0)]),
        "scene-duplicate-name": scene(
            [link("a", 0, 0), obstacle("b", 1, 0), obstacle("a", 0.5, 0)]
        ),
        "scene-nan-radius": scene(
            [link("a", 0, 0), entry("b", 2, ellipse(0, 0, special("nan"), 1, 0))]
        ),
        "scene-inf-centre": scene(
            [entry("link/1", 1, ellipse(special("inf"), 0, 1, 1, 0)), link("a", 0, 0)]
        ),
        "scene-far": scene(
            [
                entry("a", 1, ellipse(1e8, 1e8, 1, 1, 0)),
                entry("obstacle 2", 2, ellipse(1e8 + 1.5, 1e8, 1, 0.5, 0.2)),
            ]
        ),
        "scene-clamped-hostile": scene(
            [
                entry(
                    NAMES[i % len(NAMES)],
                    i % 3,
                    ellipse(
                        special("1e300"),
                        special("nan"),
                        special("-inf"),
                        special("denorm_min"),
                        special("inf"),
                    ),
                    clamp=1,
                )
                for i in range(10)
            ]
        ),
        "projection-identity": projection(ellipse(0.5, 0.2, 1, 0.3, 0.4), (0, 0, 0), angle=0.0),
        "projection-about-z": projection(ellipse(0.5, 0.2, 1, 0.3, 0.4), (1, -2, 3), angle=2.5),
        "projection-tilted": projection(
            ellipse(0, 0, 1, 1, 0), (0, 0, 0.5), quaternion=(angled, angled, 0, 0.0)
        ),
        "projection-nearly-edge-on": projection(
            ellipse(0, 0, 1, 0.5, 0), (0, 0, 0), quaternion=(1e-7, 1, 0, 0)
        ),
        "projection-far": projection(ellipse(1, 1, 1, 1, 0), (special("1e300"), 0, 0), angle=0.0),
        "projection-nan-transform": projection(
            ellipse(0, 0, 1, 1, 0), (special("nan"), 0, 0), angle=0.0
        ),
        "projection-zero-quaternion": projection(
            ellipse(0, 0, 1, 1, 0), (0, 0, 0), quaternion=(0, 0, 0, 0)
        ),
        "projection-inf-angle": projection(ellipse(0, 0, 1, 1, 0), (0, 0, 0), angle=special("inf")),
        "projection-invalid-ellipse": projection(ellipse(0, 0, -1, 1, 0), (0, 0, 0), angle=1.0),
    }


# ------------------------------------------------------------------------ fuzz_obstacle_store
def store_seeds():
    header = "ellipse_collision obstacle store 1\n"
    session = "session 36:8504ad16-e750-11f1-8eb7-02fc00000001\n"
    return {
        "good": (header + session + "topic_stamp 1795446863.200178\n"
                 "service 3:box 9:base_link 0.1 -0.3333333333333333 0.1 0.3 1e-09 0.05 0.25 "
                 "-0.14285714285714285 3e-05\n"
                 "topic 10:obstacle_0 3:map -6.923861254296241 -0.9759667199353004 "
                 "-0.521537504916425 0.16168981344598082 0.032285471898496884 0 0 0 0\n"
                 "end\n").encode(),
        "seventeen-digits": (header + "session 0:\ntopic_stamp 0\n"
                             "service 1:a 3:map 0.10000000000000001 -0.33333333333333331 "
                             "0.10000000000000001 0.29999999999999999 1.0000000000000001e-09 "
                             "0.050000000000000003 0.25 -0.14285714285714285 "
                             "3.0000000000000001e-05\nend\n").encode(),
        "no-velocities": (header + "service 1:a 3:map 1 2 0 0.5 0.5 0\nend\n").encode(),
        "service-record": (header + session + "topic_stamp 0\nservice_revision 18446744073709551\n"
                           "service 3:box 9:base_link 0.1 2 0 0.5 0.5 0 0 0 0\nend\n").encode(),
        "name-with-newline": (header + "service 11:line\nbreak\n 4:odom 1e300 2 0 0.5 0.5 0 0 0 0"
                              "\nend\n").encode(),
        "truncated": (header + session + "topic 10:obstacle_0 3:map -6.9").encode(),
        "nan-inf": (header + "topic 1:n 3:map nan inf -inf 0.5 0.5 0 0 0 0\nend\n").encode(),
        "ellipsoid": (header + session + "topic_stamp 0\n"
                      "service 4:slab 4:odom 2 -0.3333333333333333 0.1 0.3 1e-09 0.05 0.25 "
                      "-0.14285714285714285 3e-05 0.2333333333333333 1.5707963267948966 "
                      "-0.1111111111111111 0.45\n"
                      "topic 7:cluster 3:map 1 2 0 0.5 0.5 0 0 0 0 0.3 0 0 1e9\nend\n").encode(),
        "ellipsoid-version-2": ("ellipse_collision obstacle store 2\n" + session + "topic_stamp 0\n"
                                "topic 7:cluster 3:map 1 2 0 0.5 0.5 0 0 0 0 0.3 0 0 1e9\n"
                                "end\n").encode(),
        "version-3": ("ellipse_collision obstacle store 3\n" + session + "end\n").encode(),
        "ellipsoid-tilt-without-depth": (header + "service 1:a 3:map 1 2 0 0.5 0.5 0 0 0 0 0 1 0 0"
                                         "\nend\n").encode(),
        "ten-numbers": (header + "service 1:a 3:map 1 2 0 0.5 0.5 0 0 0 0 0.1\nend\n").encode(),
        "empty": b"",
    }


# ------------------------------------------------------------------------ fuzz_pair_line_parser
def parser_seeds():
    lines = {
        "good": "0 0 1 1 0       1 0 1 1 0",
        "good-tabs-cr": "\t1.5\t-2  3 \t0.25 0.5\t\t-4e-1 7 8.125 9 -1.25 \r",
        "good-signs-exponents": "+1e-3 -.5 2E1 1. 1e+0 0 -0 +.25 3.5e-2 -3.14159",
        "good-17-digits": "0.30000000000000004 0 1 1 0 "
        "0.1 0.2 0.30000000000000004 1 3.141592653589793",
        "good-thin-far": "1e8 -1e8 1e3 1e-3 0.5 1.00000001e8 -1e8 1e-3 1e3 -0.5",
        "good-range-edges": "1e9 -1e9 1e9 1e-9 6.283185307179586 "
        "-1e9 1e9 1e-9 1e9 -3.141592653589793",
        "comment": "# a comment 1 2 3",
        "comment-indented": "  \t# indented comment",
        "blank": "   \t  ",
        "empty": "",
        "nine-fields": "0 0 1 1 0 1 0 1 1",
        "eleven-fields": "0 0 1 1 0 1 0 1 1 0 7",
        "not-a-number": "0 0 abc 1 0 1 0 1 1 0",
        "hex-float": "0x1p3 0 1 1 0 1 0 1 1 0",
        "out-of-range": "1e999 0 1 1 0 1 0 1 1 0",
        "underflow": "1e-400 0 1 1 0 1 0 1 1 0",
        "subnormal-radius": "0 0 5e-324 1 0 1 0 1 1 0",
        "nan": "0 0 1 nan 0 1 0 1 1 0",
        "inf": "0 0 1 1 inf 1 0 1 1 0",
        "negative-radius": "0 0 -1 1 0 3 0 1 1 0",
        "zero-radius": "0 0 1 1 0 3 0 0 1 0",
        "huge-centre": "1e300 0 1 1 0 3 0 1 1 0",
        "double-sign": "+-1 0 1 1 0 1 0 1 1 0",
        "plus-only": "+ 0 1 1 0 1 0 1 1 0",
        "comma-decimal": "0,5 0 1 1 0 1 0 1 1 0",
        "control-bytes": "0 0 1\x01 1 0 1 0 1\x7f 1 0",
        "quote-and-backslash": '0 0 "1\\" 1 0 1 0 1 1 0',
        "utf8": "0 0 1\u00a01 0 1 0 1 1 0",
        "long-field": "1" * 500 + " 0 1 1 0 1 0 1 1 0",
        "long-garbage": "x" * 3000,
        "embedded-newline": "0 0 1 1 0\n1 0 1 1 0",
        "nul-byte": "0 0 1 1 0\x001 0 1 1 0",
    }
    return {name: text.encode("utf-8") for name, text in lines.items()}


# ------------------------------------------------------------------------------- fuzz_ros_request
# Layout: padding flag (1: no global padding, 0: 0.02 m), then up to 8 operations: kind (0 add,
# 1 remove, 2 topic message, 3 check query), entry count, per entry (name index, frame index,
# x, y, angle, radius_x, radius_y, padding flag [+ padding], ellipsoid flag [+ z, roll, pitch,
# radius_z, each a zero flag [+ number]]), and for kind 2 the header frame.
REQUEST_NAMES = ["", "body", "arm", "crate", "box", "q", "box/2", "a b", "\xff\xfe"]
REQUEST_FRAMES = ["", "base_link", "odom", "/odom", "arm_link", " ", "a\nb"]


def request_entry(name, frame, x=0.0, y=0.0, angle=0.0, rx=0.5, ry=0.25, padding=None,
                  depth=None):
    """depth: None for a planar ellipse, else (z, roll, pitch, radius_z), 0 written as a flag."""
    out = byte(REQUEST_NAMES.index(name)) + byte(REQUEST_FRAMES.index(frame))
    out += b"".join(v if isinstance(v, bytes) else num(v) for v in (x, y, angle, rx, ry))
    if padding is None:
        out += byte(1)
    else:
        out += byte(0) + (padding if isinstance(padding, bytes) else num(padding))
    if depth is None:
        return out + byte(0)
    out += byte(1)
    for value in depth:
        if not isinstance(value, bytes) and value == 0:
            out += byte(1)
        else:
            out += byte(0) + (value if isinstance(value, bytes) else num(value))
    return out


def operation(kind, entries, header_frame=None):
    out = byte(kind) + byte(len(entries)) + b"".join(entries)
    if kind == 2:
        out += byte(REQUEST_FRAMES.index(header_frame))
    return out


def request_seeds():
    add, remove, topic, query = 0, 1, 2, 3
    box = request_entry("box", "odom", 1.0, 0.5)
    return {
        "add-check-remove": byte(1)
        + operation(add, [box])
        + operation(query, [request_entry("q", "base_link")])
        + operation(remove, [request_entry("box", "")]),
        "add-replace-configured": byte(0)
        + operation(add, [request_entry("crate", "base_link", padding=0.1)]),
        "add-link-name": byte(1) + operation(add, [request_entry("body", "base_link")]),
        "add-duplicates": byte(1) + operation(add, [box, box]),
        "add-hostile-fields": byte(1)
        + operation(add, [request_entry("box", "odom", special("nan"), 0, 0, 1, 1)])
        + operation(add, [request_entry("box", "odom", 0, 0, 0, special("1e-12"), 1)])
        + operation(add, [request_entry("box", "odom", 0, 0, 0, 1, 1, special("inf"))])
        + operation(add, [request_entry("box", "/odom")])
        + operation(add, [request_entry("", "odom")]),
        "add-range-edges": byte(1)
        + operation(
            add,
            [
                request_entry(
                    "box",
                    "odom",
                    special("max_coordinate"),
                    0,
                    0,
                    special("max_radius"),
                    special("min_radius"),
                )
            ],
        ),
        "remove-link-and-unknown": byte(1)
        + operation(remove, [request_entry("arm", "")])
        + operation(remove, [request_entry("q", "")])
        + operation(remove, [request_entry("", "")]),
        "topic-inherits-header-frame": byte(1)
        + operation(topic, [request_entry("box", ""), request_entry("q", "odom")], "odom")
        + operation(topic, [request_entry("box/2", "")], "base_link")
        + operation(remove, [request_entry("box/2", "")]),
        "topic-takes-configured-name": byte(1)
        + operation(topic, [request_entry("crate", "")], "odom"),
        "topic-without-any-frame": byte(1) + operation(topic, [request_entry("box", "")], ""),
        "query-hostile": byte(1)
        + operation(
            query,
            [
                request_entry("q", "base_link", special("1e300")),
                request_entry("a b", "a\nb", 0, 0, special("-inf")),
            ],
        ),
        "add-ellipsoid-and-query-it": byte(1)
        + operation(add, [request_entry("box", "odom", 1.0, 0.5, depth=(0.2, 1.5, 0, 0.4))])
        + operation(
            query, [request_entry("q", "odom", 1.0, 0.9, depth=(0, 0, -0.3, 0.1))]
        )
        + operation(topic, [request_entry("box/2", "", depth=(0, 0, 0, 0.05))], "base_link"),
        "add-ellipsoid-hostile-depth": byte(1)
        + operation(add, [request_entry("box", "odom", depth=(0, 0, 0, special("nan")))])
        + operation(add, [request_entry("box", "odom", depth=(0, 1.5, 0, 0))])
        + operation(add, [request_entry("box", "odom", depth=(0, 0, 0, -1.0))])
        + operation(add, [request_entry("box", "odom", depth=(special("inf"), 0, 0, 1.0))])
        + operation(add, [request_entry("box", "odom", depth=(0, 0, 0, special("-0")))])
        + operation(add, [request_entry("box", "odom", depth=(0, 0, 0, special("above_max_radius")))]),
        "query-duplicate-and-stored-name": byte(1)
        + operation(
            query,
            [
                request_entry("q", "odom"),
                request_entry("q", "odom"),
                request_entry("crate", "odom"),
            ],
        ),
    }


# ------------------------------------------------------------------------------- fuzz_node_config
# Layout: root (byte % 32 == 0: any value instead of a dict), key count, per key (key index,
# then its value: byte % 16 == 0 an arbitrary value, else one of the key's own type).
ROOT_KEYS = [
    "fixed_frame",
    "rate",
    "tf_timeout",
    "padding",
    "links",
    "obstacles",
    "allowed_pairs",
    "self_collision",
    "warning_distance",
    "tf_timout",
    "",
]
CONFIG_NAMES = ["body", "arm", "crate", "", "a/b", "body "]
CONFIG_FRAMES = ["base_link", "odom", "/odom", "", "arm link"]


def config_number(value):
    if isinstance(value, int):
        return byte(1) + byte(value + 103)  # an XmlRpc int: byte % 204 - 103
    return byte(0) + (value if isinstance(value, bytes) else num(value))


def config_entry(
    name,
    frame,
    x=0.0,
    y=0.0,
    angle=0.0,
    rx=0.5,
    ry=0.25,
    padding=None,
    missing=(),
    unknown=False,
    depth=None,
):
    """depth: None for a planar entry, else (z, roll, pitch, radius_z), None for a missing key."""
    out = b""
    for key, value in (
        ("name", name),
        ("frame", frame),
        ("x", x),
        ("y", y),
        ("angle", angle),
        ("radius_x", rx),
        ("radius_y", ry),
        ("padding", padding),
    ):
        if key in missing or value is None:
            out += byte(0)
        elif key == "name":
            out += byte(2) + byte(1) + byte(CONFIG_NAMES.index(value))
        elif key == "frame":
            out += byte(2) + byte(1) + byte(CONFIG_FRAMES.index(value))
        else:
            out += byte(2) + byte(1) + config_number(value)
    # z, roll, pitch, radius_z: present only with a presence byte >= 5 (7 is an arbitrary value).
    for value in depth if depth is not None else (None,) * 4:
        out += byte(0) if value is None else byte(5) + byte(1) + config_number(value)
    # "rad", a key no entry may have: present only when asked for.
    return out + (byte(1) + byte(1) + config_number(1.0) if unknown else byte(0))


def config(*keys):
    return (
        byte(1)
        + byte(len(keys))
        + b"".join(byte(ROOT_KEYS.index(k)) + byte(1) + v for k, v in keys)
    )


def entries(*items):
    return byte(len(items)) + b"".join(items)


def pairs(*items):
    return byte(len(items)) + b"".join(
        byte(1) + byte(CONFIG_NAMES.index(a)) + byte(CONFIG_NAMES.index(b)) for a, b in items
    )


def config_seeds():
    body = config_entry("body", "base_link", rx=0.5, ry=0.3)
    arm = config_entry("arm", "odom", 1, 0, 0, 0.4, 0.1, padding=0.01)
    crate = config_entry("crate", "odom", 2, 0, 0.3, 0.3, 0.2)
    good = [
        ("fixed_frame", byte(0)),
        ("rate", config_number(10.0)),
        ("links", entries(body, arm)),
        ("obstacles", entries(crate)),
        ("allowed_pairs", pairs(("body", "arm"))),
    ]
    return {
        "good": config(*good),
        "good-ints-and-options": config(
            ("links", entries(config_entry("body", "base_link", 0, 0, 0, 1, 2))),
            ("tf_timeout", config_number(0.2)),
            ("padding", config_number(0)),
            ("self_collision", byte(0)),
            ("warning_distance", config_number(0.5)),
        ),
        "empty": config(),
        "not-a-dict": byte(0) + byte(3) + byte(0),
        "missing-links": config(("rate", config_number(10.0))),
        "missing-key": config(
            ("links", entries(config_entry("body", "base_link", missing=("radius_y",))))
        ),
        "unknown-entry-key": config(
            ("links", entries(config_entry("body", "base_link", unknown=True)))
        ),
        "misspelled-key": config(("links", entries(body)), ("tf_timout", config_number(0.1))),
        "duplicate-name": config(
            ("links", entries(body)), ("obstacles", entries(config_entry("body", "odom")))
        ),
        "unknown-pair-name": config(
            ("links", entries(body, arm)), ("allowed_pairs", pairs(("body", "crate")))
        ),
        "pair-twice-the-same": config(
            ("links", entries(body)), ("allowed_pairs", pairs(("body", "body")))
        ),
        "hostile-numbers": config(
            (
                "links",
                entries(
                    config_entry("body", "base_link", special("nan"), 0, 0, 1, 1),
                    config_entry("arm", "base_link", 0, 0, 0, special("1e-12"), 1),
                ),
            )
        ),
        "ellipsoid-link-and-obstacle": config(
            ("links", entries(config_entry("body", "base_link", depth=(0.1, 0.5, None, 0.06)))),
            ("obstacles", entries(config_entry("crate", "odom", 2, 0, depth=(None, 1.5, 0, 0.4)))),
        ),
        "ellipsoid-bad-depth": config(
            (
                "obstacles",
                entries(
                    config_entry("crate", "odom", depth=(None, 1.5, None, None)),
                    config_entry("arm", "odom", depth=(None, None, None, -1.0)),
                    config_entry("body", "odom", depth=(None, 1.5, None, 0)),
                ),
            ),
        ),
        "slashed-frames": config(
            ("fixed_frame", byte(2)), ("links", entries(config_entry("body", "/odom")))
        ),
    }


# ------------------------------------------------------------------------------- open findings
def open_findings():
    """Inputs that broke a target, per target; all are fixed now, so they are also written as
    seeds and every CI run replays them as regression inputs. New findings that are not yet fixed
    go here too, while --open-findings is how to reproduce them."""
    return {
        "fuzz_ros_request": {
            # radius_x = 1e9 m passes validation; + 0.02 m of padding the core refuses it.
            "regression-radius-edge-with-padding": byte(0)
            + operation(0, [request_entry("box", "odom", 0, 0, 0, special("max_radius"), 1)]),
            # A needle ellipsoid 1e9 m away at the range's edges: every field valid, its shadow,
            # grown over the rounding of the far centre, wider than kMaxRadius; the query must be
            # refused naming it, not taken for a bug.
            "regression-ellipsoid-shadow-beyond-range": byte(1)
            + operation(
                3,
                [
                    request_entry(
                        "q",
                        "base_link",
                        special("max_coordinate"),
                        0,
                        0,
                        special("max_radius"),
                        special("min_radius"),
                        depth=(0, 0, 0.5, special("max_radius")),
                    )
                ],
            ),
        },
        "fuzz_node_config": {
            "regression-radius-edge-with-padding": config(
                (
                    "links",
                    entries(
                        config_entry(
                            "body", "base_link", 0, 0, 0, special("max_radius"), 1, padding=0.5
                        )
                    ),
                )
            ),
            "regression-tf-timeout-beyond-ros-duration": config(
                ("links", entries(config_entry("body", "base_link"))),
                ("tf_timeout", config_number(1e12)),
            ),
            "regression-rate-below-ros-duration": config(
                ("links", entries(config_entry("body", "base_link"))),
                ("rate", config_number(1e-12)),
            ),
            "regression-global-padding-beyond-core-range": config(
                ("links", entries(config_entry("body", "base_link"))),
                ("padding", config_number(1e18)),
            ),
            "regression-rate-with-zero-period": config(
                ("links", entries(config_entry("body", "base_link"))), ("rate", config_number(1e12))
            ),
        },
    }


def write(directory, seeds):
    os.makedirs(directory, exist_ok=True)
    for name in os.listdir(directory):
        if name.startswith("seed-"):
            os.remove(os.path.join(directory, name))
    for name, data in sorted(seeds.items()):
        with open(os.path.join(directory, "seed-" + name), "wb") as f:
            f.write(data)


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    if len(argv) > 2 and argv[1] == "--open-findings":
        for target, seeds in open_findings().items():
            os.makedirs(os.path.join(argv[2], target), exist_ok=True)
            for name, data in seeds.items():
                with open(os.path.join(argv[2], target, name), "wb") as f:
                    f.write(data)
        return 0
    out = argv[1] if len(argv) > 1 else os.path.join(here, "..", "test", "fuzz_corpus")
    write(os.path.join(out, "fuzz_core_pair"), core_pair_seeds())
    write(os.path.join(out, "fuzz_scene"), scene_seeds())
    write(os.path.join(out, "fuzz_pair_line_parser"), parser_seeds())
    write(os.path.join(out, "fuzz_obstacle_store"), store_seeds())
    fixed = open_findings()
    write(os.path.join(out, "fuzz_ros_request"), {**request_seeds(), **fixed["fuzz_ros_request"]})
    write(os.path.join(out, "fuzz_node_config"), {**config_seeds(), **fixed["fuzz_node_config"]})
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
