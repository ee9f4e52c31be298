"""Contact scale t* of two ellipses in 40-digit arithmetic (mpmath), for the Python tests and the
Python benchmark: the Python twin of contact_scale_oracle.cpp, independent of the core's
eigenvalue method.

t* is the gauge of d = c_b - c_a with respect to the Minkowski sum of the two centred ellipses,
    t* = max over unit u of (u . d) / (h_a(u) + h_b(u)),   h(u) = sqrt(u^T S u),
a unimodal function of the angle of u: a dense float64 grid finds the peak's neighbourhood, a
golden-section search in 40 digits narrows it until t*'s error (the peak's curvature times the
bracket's width squared) is far below 1e-30. The ellipses overlap iff t* <= 1. Ellipses are rows
(x, y, radius_x, radius_y, angle) of floats, read exactly.
"""
import math

import mpmath
import numpy

DIGITS = 40
SAMPLES = 4096
# Golden-section steps: shrink the bracket of 4 grid steps (6e-3 rad) below 1e-20 rad.
GOLDEN_STEPS = 100


def _axes(row, sin_cos):
    """(c, s, rx^2, ry^2) of an ellipse row: h(u)^2 = rx^2 (u . e_x)^2 + ry^2 (u . e_y)^2."""
    sin, cos = sin_cos
    angle = row[4]
    return cos(angle), sin(angle), row[2] * row[2], row[3] * row[3]


def _support(axes, ux, uy, sqrt):
    c, s, rx2, ry2 = axes
    along_x = c * ux + s * uy
    along_y = c * uy - s * ux
    return sqrt(rx2 * along_x * along_x + ry2 * along_y * along_y)


def contact_scale(a, b):
    """t* of rows a and b as an mpmath number (40 digits); 0 when the centres coincide."""
    with mpmath.workdps(DIGITS):
        dx = mpmath.mpf(b[0]) - mpmath.mpf(a[0])
        dy = mpmath.mpf(b[1]) - mpmath.mpf(a[1])
        if dx == 0 and dy == 0:
            return mpmath.mpf(0)
        # Grid in float64: only the position of the peak matters here.
        phi = numpy.linspace(0.0, 2.0 * math.pi, SAMPLES, endpoint=False)
        ux, uy = numpy.cos(phi), numpy.sin(phi)
        fa = _axes(a, (math.sin, math.cos))
        fb = _axes(b, (math.sin, math.cos))
        ratio = (ux * float(dx) + uy * float(dy)) / (
            _support(fa, ux, uy, numpy.sqrt) + _support(fb, ux, uy, numpy.sqrt))
        best = int(numpy.argmax(ratio))
        step = 2.0 * math.pi / SAMPLES

        qa = _axes([mpmath.mpf(v) for v in a], (mpmath.sin, mpmath.cos))
        qb = _axes([mpmath.mpf(v) for v in b], (mpmath.sin, mpmath.cos))

        def f(angle):
            cx, cy = mpmath.cos(angle), mpmath.sin(angle)
            return (cx * dx + cy * dy) / (_support(qa, cx, cy, mpmath.sqrt) +
                                          _support(qb, cx, cy, mpmath.sqrt))

        low = mpmath.mpf(phi[best]) - 2 * mpmath.mpf(step)
        high = mpmath.mpf(phi[best]) + 2 * mpmath.mpf(step)
        golden = (mpmath.sqrt(5) - 1) / 2
        x1, x2 = high - golden * (high - low), low + golden * (high - low)
        f1, f2 = f(x1), f(x2)
        for _ in range(GOLDEN_STEPS):
            if f1 < f2:
                low, x1, f1 = x1, x2, f2
                x2 = low + golden * (high - low)
                f2 = f(x2)
            else:
                high, x2, f2 = x2, x1, f1
                x1 = high - golden * (high - low)
                f1 = f(x1)
        return max(f1, f2)


def overlaps(a, b):
    """True iff the oracle's t* <= 1: the closed ellipses share a point."""
    return contact_scale(a, b) <= 1


def placed_at(a, b, target):
    """Row b moved along d = c_b - c_a so that t* becomes `target` (t* is homogeneous of degree
    1 in d). The centre is rounded to float64: re-measure t* rather than trust `target`."""
    t = contact_scale(a, b)
    with mpmath.workdps(DIGITS):
        factor = mpmath.mpf(target) / t
        x = float(mpmath.mpf(a[0]) + (mpmath.mpf(b[0]) - mpmath.mpf(a[0])) * factor)
        y = float(mpmath.mpf(a[1]) + (mpmath.mpf(b[1]) - mpmath.mpf(a[1])) * factor)
    return [x, y, b[2], b[3], b[4]]


def near_tangent_pairs(random, count, delta, side, max_axis_ratio=100.0):
    """`count` random pairs placed at t* = 1 + side * delta, with their re-measured t*: a list of
    (a, b, t*). `random` is a random.Random; radii 0.1..10 m, axis ratios up to max_axis_ratio."""
    pairs = []
    while len(pairs) < count:
        a = _random_row(random, max_axis_ratio)
        b = _random_row(random, max_axis_ratio)
        if a[0] == b[0] and a[1] == b[1]:
            continue
        b = placed_at(a, b, 1.0 + side * delta)
        pairs.append((a, b, contact_scale(a, b)))
    return pairs


def _random_row(random, max_axis_ratio):
    radius_x = math.exp(random.uniform(math.log(0.1), math.log(10.0)))
    radius_y = radius_x / math.exp(random.uniform(0.0, math.log(max_axis_ratio)))
    if random.random() < 0.5:
        radius_x, radius_y = radius_y, radius_x
    return [random.uniform(-5.0, 5.0), random.uniform(-5.0, 5.0), radius_x, radius_y,
            random.uniform(-math.pi, math.pi)]
