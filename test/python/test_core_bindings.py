#!/usr/bin/env python3
"""The Python bindings (ellipse_collision.core) against the C++ tool check_ellipses, closed forms,
the 40-digit contact scale oracle (test/support/contact_scale_oracle.py) near tangency, and their
refusals of bad input.

usage: test_core_bindings.py CHECK_ELLIPSES_BIN [--gtest_output=xml:FILE]
(run by `catkin_make run_tests` after `source devel/setup.bash`, see cmake/test.cmake)
"""
import math
import os
import random
import subprocess
import sys
import threading
import unittest

import numpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "support"))
import contact_scale_oracle  # noqa: E402

from ellipse_collision import core  # noqa: E402

CHECK_ELLIPSES = None  # set from the command line
EXAMPLE_PAIRS = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "examples",
                             "pairs.txt")


def random_rows(generator, count, spread=4.0, max_axis_ratio=50.0):
    """(count, 5) float64 rows of random ellipses, some apart, some overlapping."""
    rows = []
    for _ in range(count):
        radius_x = math.exp(generator.uniform(math.log(0.05), math.log(3.0)))
        radius_y = radius_x / math.exp(generator.uniform(0.0, math.log(max_axis_ratio)))
        rows.append([generator.uniform(-spread, spread), generator.uniform(-spread, spread),
                     radius_x, radius_y, generator.uniform(-4.0, 4.0)])
    return numpy.array(rows, dtype=numpy.float64)


def ellipse(row):
    return core.Ellipse(*[float(v) for v in row])


def check_ellipses(lines, *options):
    """check_ellipses' answer lines for input lines (exit status 0 asserted)."""
    done = subprocess.run([CHECK_ELLIPSES] + list(options), input="\n".join(lines) + "\n",
                          stdout=subprocess.PIPE, universal_newlines=True, check=True)
    return done.stdout.split("\n")[:-1]


def text(row):
    return " ".join(repr(float(v)) for v in row)


class AgreesWithTheCppTool(unittest.TestCase):
    """The same core through Python and through check_ellipses: the same bits."""

    def test_random_pairs_scalar_batch_and_tool_agree_bit_for_bit(self):
        generator = random.Random(7)
        a, b = random_rows(generator, 400, spread=1.5), random_rows(generator, 400, spread=1.5)
        answers = check_ellipses([text(ra) + " " + text(rb) for ra, rb in zip(a, b)])
        overlap = core.overlap_batch(a, b)
        scale = core.contact_scale_batch(a, b)
        self.assertEqual(overlap.dtype, numpy.bool_)
        self.assertEqual(overlap.shape, (400,))
        collisions = 0
        for i, answer in enumerate(answers):
            word, value = answer.split()
            ea, eb = ellipse(a[i]), ellipse(b[i])
            self.assertEqual(core.overlap(ea, eb), word == "collision", answer)
            self.assertEqual(bool(overlap[i]), word == "collision", answer)
            self.assertEqual(core.contact_scale(ea, eb), float(value), answer)
            self.assertEqual(scale[i], float(value), answer)
            collisions += word == "collision"
        self.assertGreater(collisions, 40)
        self.assertLess(collisions, 360)

    def test_the_example_pairs_file_gives_the_tools_answers(self):
        lines = [l.split("#")[0].split() for l in open(EXAMPLE_PAIRS)]
        pairs = [[float(v) for v in l] for l in lines if l]
        good = [p for p in pairs if p[2] > 0 and p[3] > 0 and p[7] > 0 and p[8] > 0]
        self.assertEqual(len(good), len(pairs) - 1)  # one line is bad on purpose
        answers = check_ellipses([text(p) for p in good])
        for pair, answer in zip(good, answers):
            a, b = core.Ellipse(*pair[:5]), core.Ellipse(*pair[5:])
            word, value = answer.split()
            self.assertEqual(core.overlap(a, b), word == "collision")
            self.assertEqual(core.contact_scale(a, b), float(value))

    def test_first_contact_matches_the_tools_motion_mode(self):
        generator = random.Random(11)
        lines, cases, rows = [], [], ([], [], [], [])
        for _ in range(60):
            ra, rb = random_rows(generator, 2, spread=2.0)
            ma = [generator.uniform(-2, 2), generator.uniform(-2, 2),
                  generator.choice([0.0, generator.uniform(-1, 1)])]
            mb = [generator.uniform(-2, 2), generator.uniform(-2, 2),
                  generator.choice([0.0, generator.uniform(-1, 1)])]
            horizon = generator.uniform(0.5, 5.0)
            lines.append(" ".join([text(ra), text(ma), text(rb), text(mb), repr(horizon)]))
            cases.append((ellipse(ra), core.Motion(*ma), ellipse(rb), core.Motion(*mb), horizon))
            for column, row in zip(rows, (ra, ma, rb, mb)):
                column.append(row)
        # The batch form, one horizon for all: the same bits as one pair at a time.
        batch_contacts, batch_times = core.first_contact_batch(
            *[numpy.array(column, dtype=float) for column in rows], 2.5)
        for i, (ea, ma, eb, mb, _) in enumerate(cases):
            single = core.first_contact(ea, ma, eb, mb, 2.5)
            self.assertEqual((bool(batch_contacts[i]), batch_times[i]),
                             (single.contact, single.time))
        self.assertGreater(batch_contacts.sum(), 5)
        contacts = 0
        for case, answer in zip(cases, check_ellipses(lines, "--motion")):
            result = core.first_contact(*case)
            if answer == "clear":
                self.assertFalse(result.contact, answer)
            else:
                self.assertTrue(result.contact, answer)
                self.assertEqual(result.time, float(answer.split()[1]), answer)
                contacts += 1
        self.assertGreater(contacts, 5)


class NearTangencyAgainstTheOracle(unittest.TestCase):
    """Pairs placed at t* = 1 -+ delta (re-measured in 40 digits) are classified like the oracle."""

    def test_overlap_and_contact_scale_near_tangency(self):
        generator = random.Random(3)
        for delta in (1e-3, 1e-6, 1e-9):
            for side in (-1, 1):
                pairs = contact_scale_oracle.near_tangent_pairs(generator, 25, delta, side)
                a = numpy.array([p[0] for p in pairs])
                b = numpy.array([p[1] for p in pairs])
                overlap = core.overlap_batch(a, b)
                scale = core.contact_scale_batch(a, b)
                for i, (ra, rb, oracle) in enumerate(pairs):
                    # The placement rounds the centre: the re-measured t* stays on its side.
                    self.assertEqual(oracle <= 1, side < 0, (delta, side, ra, rb))
                    self.assertEqual(bool(overlap[i]), side < 0, (delta, side, ra, rb))
                    self.assertEqual(core.overlap(ellipse(ra), ellipse(rb)), side < 0)
                    self.assertLessEqual(abs(scale[i] - float(oracle)), 1e-9 * float(oracle),
                                         (delta, side, ra, rb))

    def test_the_oracle_matches_closed_forms(self):
        # Two circles: t* = |d| / (r_a + r_b). Tip to tip along x: t* = |dx| / (rx_a + rx_b).
        self.assertAlmostEqual(float(contact_scale_oracle.contact_scale(
            [0, 0, 1, 1, 0], [3, 4, 2, 2, 0])), 5.0 / 3.0, places=14)
        self.assertAlmostEqual(float(contact_scale_oracle.contact_scale(
            [1, 0, 2, 0.5, 0], [7, 0, 1, 0.25, 0])), 2.0, places=14)


class Distance(unittest.TestCase):
    def test_axis_aligned_pair_has_its_closed_form(self):
        clearance = core.distance(core.Ellipse(0, 0, 2, 1), core.Ellipse(5, 0, 1, 1))
        self.assertTrue(clearance.separated)
        self.assertAlmostEqual(clearance.distance, 2.0, places=12)
        self.assertAlmostEqual(clearance.point_a[0], 2.0, places=9)
        self.assertAlmostEqual(clearance.point_b[0], 4.0, places=9)

    def test_witness_points_certify_the_distance(self):
        # On both rims, |point_b - point_a| = distance, and point_b - point_a is normal to both.
        generator = random.Random(5)
        a, b = random_rows(generator, 300, spread=8.0), random_rows(generator, 300, spread=8.0)
        distances, points_a, points_b = core.distance_batch(a, b)
        overlap = core.overlap_batch(a, b)
        separated = 0
        for i in range(len(a)):
            clearance = core.distance(ellipse(a[i]), ellipse(b[i]))
            self.assertEqual(clearance.distance, distances[i])
            self.assertEqual(clearance.separated, not overlap[i])
            if overlap[i]:
                self.assertEqual(distances[i], 0.0)
                continue
            separated += 1
            gap = points_b[i] - points_a[i]
            self.assertAlmostEqual(float(numpy.hypot(*gap)), distances[i],
                                   delta=1e-9 * max(1.0, distances[i]))
            for row, point, sign in ((a[i], points_a[i], 1.0), (b[i], points_b[i], -1.0)):
                c, s = math.cos(row[4]), math.sin(row[4])
                local = ((point[0] - row[0]) * c + (point[1] - row[1]) * s,
                         -(point[0] - row[0]) * s + (point[1] - row[1]) * c)
                self.assertAlmostEqual((local[0] / row[2]) ** 2 + (local[1] / row[3]) ** 2, 1.0,
                                       delta=1e-9)
                if distances[i] > 1e-6:
                    normal = (local[0] / row[2] ** 2, local[1] / row[3] ** 2)
                    normal = (normal[0] * c - normal[1] * s, normal[0] * s + normal[1] * c)
                    cross = normal[0] * gap[1] - normal[1] * gap[0]
                    dot = sign * (normal[0] * gap[0] + normal[1] * gap[1])
                    self.assertGreater(dot, 0.0)
                    self.assertLess(abs(cross), 1e-7 * math.hypot(*normal) * math.hypot(*gap))
        self.assertGreater(separated, 100)


class FirstContact(unittest.TestCase):
    def test_approaching_circles_touch_at_the_closed_form_time(self):
        # Gap 2 m closed at 0.5 + 1.5 m/s: contact after 1 s.
        result = core.first_contact(core.Ellipse(0, 0, 1, 1), core.Motion(0.5, 0),
                                    core.Ellipse(4, 0, 1, 1), core.Motion(-1.5, 0), 10.0)
        self.assertTrue(result.contact)
        self.assertAlmostEqual(result.time, 1.0, places=12)
        miss = core.first_contact(core.Ellipse(0, 0, 1, 1), core.Motion(),
                                  core.Ellipse(4, 0, 1, 1), core.Motion(0, 1), 10.0)
        self.assertFalse(miss.contact)


class EnclosingEllipse(unittest.TestCase):
    def test_rectangle_corners_give_the_sqrt2_scaled_ellipse(self):
        # The minimum-area ellipse of a 2a x 2b rectangle has radii a sqrt(2), b sqrt(2).
        points = numpy.array([[3, 1], [-3, 1], [-3, -1], [3, -1], [0, 0.5]], dtype=float)
        result = core.minimum_area_ellipse(points)
        self.assertEqual(result.status, "ok")
        self.assertAlmostEqual(result.ellipse.radius_x, 3 * math.sqrt(2), delta=1e-8)
        self.assertAlmostEqual(result.ellipse.radius_y, math.sqrt(2), delta=1e-8)
        self.assertAlmostEqual(result.ellipse.x, 0.0, delta=1e-9)

    def test_collinear_points_are_degenerate_and_grow_with_a_min_radius(self):
        points = numpy.array([[0, 0], [1, 1], [2, 2]], dtype=float)
        self.assertEqual(core.minimum_area_ellipse(points).status, "degenerate")
        self.assertIsNone(core.minimum_area_ellipse(points).ellipse)
        grown = core.enclosing_ellipse_with_min_radius(points, 0.1)
        self.assertEqual(grown.status, "ok")
        self.assertGreaterEqual(grown.ellipse.radius_y, 0.1)


class SceneCheck(unittest.TestCase):
    def scene(self):
        return [("arm", core.Role.LINK, core.Ellipse(0, 0, 1, 0.3)),
                ("base", core.Role.LINK, core.Ellipse(0.5, 0, 1, 1)),
                ("box", core.Role.OBSTACLE, core.Ellipse(1.3, 0, 0.5, 0.5)),
                ("wall", core.Role.OBSTACLE, core.Ellipse(0, 3, 5, 0.2))]

    def test_collisions_warnings_and_rules(self):
        result = core.check_scene(self.scene(), warning_distance=3.0)
        self.assertEqual([(p.name_a, p.name_b) for p in result.collisions],
                         [("arm", "base"), ("arm", "box"), ("base", "box")])
        arm_box = core.contact_scale(core.Ellipse(0, 0, 1, 0.3), core.Ellipse(1.3, 0, 0.5, 0.5))
        self.assertEqual(result.collisions[1].contact_scale, arm_box)
        self.assertEqual([(p.name_a, p.name_b) for p in result.warnings],
                         [("arm", "wall"), ("base", "wall")])
        self.assertAlmostEqual(result.warnings[0].distance, 3 - 0.2 - 0.3, places=9)
        ruled = core.check_scene(self.scene(), self_collision=False,
                                 allowed_pairs=[("box", "base")], only_names={"box"})
        self.assertEqual([(p.name_a, p.name_b) for p in ruled.collisions], [("arm", "box")])


class BadInputIsRefused(unittest.TestCase):
    def assertRefused(self, message, function, *args, **kwargs):
        with self.assertRaises(ValueError) as caught:
            function(*args, **kwargs)
        self.assertEqual(str(caught.exception), message)

    def test_ellipse_fields(self):
        self.assertRefused("radius_x = -1 must be > 0", core.Ellipse, 0, 0, -1, 1, 0)
        self.assertRefused("center.x = nan is not finite", core.Ellipse, math.nan, 0, 1, 1, 0)
        self.assertRefused("angle = inf is not finite", core.Ellipse, 0, 0, 1, 1, math.inf)
        self.assertRefused("radius_y = 1e+10 is outside [1e-09, 1e+09] m",
                           core.Ellipse, 0, 0, 1, 1e10, 0)

    def test_batch_arrays(self):
        good = numpy.zeros((3, 5))
        good[:, 2:4] = 1.0
        self.assertRefused("a: shape (3, 4), expected (N, 5): rows [x, y, radius_x, radius_y, "
                           "angle]", core.overlap_batch, good[:, :4], good)
        self.assertRefused("b: shape (5,), expected (N, 5): rows [x, y, radius_x, radius_y, "
                           "angle]", core.overlap_batch, good, good[0])
        self.assertRefused("a: dtype int64, expected float64", core.contact_scale_batch,
                           good.astype(numpy.int64), good)
        self.assertRefused("b: dtype float32, expected float64", core.distance_batch,
                           good, good.astype(numpy.float32))
        self.assertRefused("a has 3 rows and b 2: one pair per row, the same number of rows in "
                           "both", core.overlap_batch, good, good[:2])
        bad = good.copy()
        bad[2, 3] = -1.0
        self.assertRefused("b[2]: radius_y = -1 must be > 0", core.overlap_batch, good, bad)
        bad[1, 0] = math.nan
        self.assertRefused("a[1]: center.x = nan is not finite", core.contact_scale_batch, bad,
                           good)

    def test_motion_points_and_scene(self):
        e = core.Ellipse(0, 0, 1, 1)
        self.assertRefused("horizon = -1 must be >= 0", core.first_contact, e, core.Motion(),
                           e, core.Motion(), -1.0)
        self.assertRefused("motion 2: angular_velocity = nan must be finite", core.first_contact,
                           e, core.Motion(), e, core.Motion(0, 0, math.nan), 1.0)
        rows, motions = numpy.tile([[0.0, 0, 1, 1, 0]], (2, 1)), numpy.zeros((2, 3))
        self.assertRefused("motion_b: shape (2, 2), expected (N, 3): rows [vx, vy, "
                           "angular_velocity]", core.first_contact_batch, rows, motions, rows,
                           motions[:, :2], 1.0)
        self.assertRefused("motion_a has 1 rows and a 2: one motion per ellipse",
                           core.first_contact_batch, rows, motions[:1], rows, motions, 1.0)
        bad = motions.copy()
        bad[1, 2] = math.nan
        self.assertRefused("pair 1: motion 2: angular_velocity = nan must be finite",
                           core.first_contact_batch, rows, motions, rows, bad, 1.0)
        self.assertRefused("pair 0: horizon = -1 must be >= 0", core.first_contact_batch, rows,
                           motions, rows, motions, -1.0)
        self.assertRefused("points[1].y = nan is not finite", core.minimum_area_ellipse,
                           numpy.array([[0, 0], [1, math.nan], [2, 0]]))
        self.assertRefused("points: shape (2, 3), expected (N, 2): rows [x, y]",
                           core.minimum_area_ellipse, numpy.zeros((2, 3)))
        with self.assertRaises(ValueError) as caught:
            core.check_scene([("arm", core.Role.LINK, e), ("arm", core.Role.OBSTACLE, e)])
        self.assertIn("arm", str(caught.exception))
        with self.assertRaises(ValueError) as caught:
            core.check_scene([("arm", core.Role.LINK, e)], warning_distance=-1.0)
        self.assertIn("warning_distance = -1", str(caught.exception))


class EllipseBatchOfAFixedSet(unittest.TestCase):
    """core.EllipseBatch answers as overlap() on every pair: far, near, overlapping and within
    1e-9 of tangency (where the oracle decides)."""

    def test_overlap_with_and_overlap_rows_agree_with_overlap(self):
        generator = random.Random(21)
        # Spread over 40 m: most of the set is far from any one query, which the culling decides.
        obstacles = numpy.vstack([random_rows(generator, 600, spread=20.0),
                                  random_rows(generator, 200, spread=2.0)])
        batch = core.EllipseBatch(obstacles)
        self.assertEqual(len(batch), 800)
        hits = 0
        for query_row in random_rows(generator, 40, spread=4.0):
            query = ellipse(query_row)
            answers = batch.overlap_with(query)
            self.assertEqual(answers.dtype, numpy.bool_)
            expected = [core.overlap(query, ellipse(row)) for row in obstacles]
            self.assertEqual(answers.tolist(), expected)
            hits += sum(expected)
        self.assertGreater(hits, 100)
        others = random_rows(generator, 800, spread=20.0)
        numpy.testing.assert_array_equal(batch.overlap_rows(core.EllipseBatch(others)),
                                         core.overlap_batch(obstacles, others))

    def test_near_tangency_against_the_oracle(self):
        generator = random.Random(22)
        for delta in (1e-6, 1e-9):
            for side in (-1, 1):
                pairs = contact_scale_oracle.near_tangent_pairs(generator, 25, delta, side)
                a = core.EllipseBatch(numpy.array([p[0] for p in pairs]))
                b = core.EllipseBatch(numpy.array([p[1] for p in pairs]))
                self.assertEqual(a.overlap_rows(b).tolist(), [side < 0] * len(pairs))
                for ra, rb, _ in pairs:
                    one = core.EllipseBatch(numpy.array([rb]))
                    self.assertEqual(one.overlap_with(ellipse(ra)).tolist(), [side < 0])

    def test_bad_rows_and_sizes_are_refused(self):
        rows = random_rows(random.Random(23), 3)
        rows[2, 3] = -1.0
        with self.assertRaises(ValueError) as caught:
            core.EllipseBatch(rows)
        self.assertEqual(str(caught.exception), "rows[2]: radius_y = -1 must be > 0")
        with self.assertRaises(ValueError) as caught:
            core.EllipseBatch(numpy.zeros((2, 5), dtype=numpy.float32))
        self.assertIn("rows: dtype float32, expected float64", str(caught.exception))
        good = core.EllipseBatch(random_rows(random.Random(24), 3))
        with self.assertRaises(ValueError) as caught:
            good.overlap_rows(core.EllipseBatch(random_rows(random.Random(25), 2)))
        self.assertIn("3 ellipses and the other 2", str(caught.exception))
        self.assertEqual(core.EllipseBatch(numpy.zeros((0, 5))).overlap_with(
            core.Ellipse(0.0, 0.0, 1.0, 1.0)).shape, (0,))


class BatchArrays(unittest.TestCase):
    def test_strided_views_give_the_answers_of_contiguous_copies(self):
        generator = random.Random(9)
        wide = numpy.asfortranarray(random_rows(generator, 200))
        other = random_rows(generator, 400)[::2]
        self.assertFalse(other.flags.c_contiguous)
        numpy.testing.assert_array_equal(
            core.contact_scale_batch(wide, other),
            core.contact_scale_batch(numpy.ascontiguousarray(wide), numpy.ascontiguousarray(other)))
        self.assertEqual(core.overlap_batch(numpy.zeros((0, 5)), numpy.zeros((0, 5))).shape, (0,))

    def test_other_threads_run_during_a_batch(self):
        # The loop releases the GIL: a Python thread counting meanwhile gets to count.
        generator = random.Random(13)
        a, b = random_rows(generator, 20000), random_rows(generator, 20000)
        a, b = numpy.tile(a, (25, 1)), numpy.tile(b, (25, 1))
        counted = [0]
        running = threading.Event()
        done = threading.Event()

        def count():
            running.set()
            while not done.is_set():
                counted[0] += 1

        counter = threading.Thread(target=count)
        counter.start()
        running.wait()
        before = counted[0]
        core.overlap_batch(a, b)
        during = counted[0] - before
        done.set()
        counter.join()
        self.assertGreater(during, 1000)


if __name__ == "__main__":
    CHECK_ELLIPSES = sys.argv[1]
    import rosunit
    # "__main__" names this module: every TestCase above.
    rosunit.unitrun("ellipse_collision", "python_core_bindings", "__main__",
                    sys.argv[:1] + [a for a in sys.argv[2:] if a.startswith("--gtest_output")])
