#!/usr/bin/env python3
"""rostest: `rosrun ellipse_collision check_collisions_client.py` against the example config.

The expected contact scales are computed by hand, independently of the node: every ellipse
involved lies on base_link's x axis with its axes along it, so two of them touch when scaled by
t about their centres iff t * (sum of their semi-axes along x) = distance of their centres.
  box     circle 0.2 m + 0.02 m global padding = 0.22 m at x = 0.6
  bumper  0.05 + 0.01 + 0.02 = 0.08 m along x at x = 0.45  ->  t = 0.15 / 0.30 = 0.5
  chassis 0.45 + 0.02 = 0.47 m along x at x = 0            ->  t = 0.60 / 0.69 = 0.869565...
"""
import re
import subprocess
import sys
import unittest

import rostest

PKG = "ellipse_collision"


class PythonClientTest(unittest.TestCase):
    def test_example_client_adds_box_and_reports_its_collisions(self):
        done = subprocess.run(["rosrun", PKG, "check_collisions_client.py", "--timeout", "30"],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              universal_newlines=True, timeout=90)
        out = done.stdout
        self.assertEqual(done.returncode, 0, out)
        self.assertIn("add_obstacles: success=True message='added 1 obstacle(s)'", out)
        self.assertIn("check_collisions: success=True in_collision=True", out)
        scales = {(a, b): float(t) for a, b, t in
                  re.findall(r"collision (\w+) - (\w+), contact_scale ([0-9.]+)", out)}
        self.assertEqual(set(scales), {("bumper", "box"), ("chassis", "box")}, out)
        self.assertAlmostEqual(scales[("bumper", "box")], 0.15 / 0.30, places=6)
        self.assertAlmostEqual(scales[("chassis", "box")], 0.60 / 0.69, places=6)
        # It collides, so its nearest partner is the one of smallest contact scale, at 0 m.
        self.assertIn("nearest to box: bumper at 0.000000 m", out)
        # gripper hangs on arm_link, which nothing publishes in this test.
        self.assertIn("frame unavailable: arm_link", out)


if __name__ == "__main__":
    rostest.rosrun(PKG, "python_client", PythonClientTest, sys.argv)
