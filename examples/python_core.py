#!/usr/bin/env python3
"""ellipse_collision.core from Python: one pair, a moving pair, many pairs from numpy, a scene.

Run after `source build/ws/devel/setup.bash` with Debian's python3 (doc/python.md).
"""
import numpy

from ellipse_collision import core

# Centre (x, y) [m], semi-axes radius_x, radius_y [m], angle [rad] counter-clockwise.
arm = core.Ellipse(x=0.0, y=0.0, radius_x=1.0, radius_y=0.3, angle=0.5)
box = core.Ellipse(x=1.2, y=0.4, radius_x=0.5, radius_y=0.5)
print("arm and box overlap: %s, contact scale %.6f" % (core.overlap(arm, box),
                                                       core.contact_scale(arm, box)))

cart = core.Ellipse(x=3.0, y=0.0, radius_x=0.5, radius_y=0.5)
clearance = core.distance(arm, cart)
print("arm to cart: %.6f m, from (%.6f, %.6f) to (%.6f, %.6f)"
      % ((clearance.distance,) + clearance.point_a + clearance.point_b))

# The cart drives towards the arm at 1 m/s: when do they touch within 5 s?
contact = core.first_contact(arm, core.Motion(), cart, core.Motion(vx=-1.0), horizon=5.0)
print("first contact: %s after %.6f s" % (contact.contact, contact.time))

# Many pairs at once: (N, 5) float64 rows [x, y, radius_x, radius_y, angle]; row i of a with
# row i of b, looped in C++.
a = numpy.array([[0.0, 0.0, 1.0, 0.5, 0.0]] * 3)
b = numpy.array([[1.4, 0.0, 0.5, 0.5, 0.0],
                 [1.6, 0.0, 0.5, 0.5, 0.0],
                 [0.0, 0.9, 0.5, 0.5, 1.0]])
print("overlap_batch:", core.overlap_batch(a, b).tolist())

# Bad input is refused with the field and its value.
try:
    core.Ellipse(x=0.0, y=0.0, radius_x=-1.0, radius_y=0.5)
except ValueError as error:
    print("refused:", error)

# A scene of named ellipses: link-obstacle pairs in collision, and near misses within 2 m.
scene = [("arm", core.Role.LINK, arm), ("box", core.Role.OBSTACLE, box),
         ("cart", core.Role.OBSTACLE, cart)]
result = core.check_scene(scene, warning_distance=2.0)
for pair in result.collisions:
    print("collision: %s - %s" % (pair.name_a, pair.name_b))
for pair in result.warnings:
    print("warning: %s - %s at %.6f m" % (pair.name_a, pair.name_b, pair.distance))
